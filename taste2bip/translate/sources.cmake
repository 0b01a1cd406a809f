# The translation: ASN.1 values as BIP data, function signatures, atoms and the package.
list(APPEND TASTE2BIP_SOURCES
  translate/bip_types.cpp
  translate/signature.cpp)
# The SDL process translation lists its sources apart.
include(translate/sdl_sources.cmake)
