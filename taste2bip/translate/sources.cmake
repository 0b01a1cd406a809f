# The translation: ASN.1 values as BIP data, function signatures, atoms and the packages.
list(APPEND TASTE2BIP_SOURCES
  translate/bip_types.cpp
  translate/signature.cpp
  translate/abstract_atom.cpp
  translate/c_types.cpp
  translate/c_shim.cpp
  translate/c_body.cpp
  translate/c_body_atom.cpp
  translate/package_parts.cpp
  translate/connect.cpp
  translate/faulty_package.cpp
  translate/package.cpp
  translate/read_design.cpp
  translate/bipc_diagnostics.cpp)
# The SDL process translation lists its sources apart.
include(translate/sdl_sources.cmake)
