# Checker sources. Core (symbols, expressions, atoms, connectors, driver):
list(APPEND BIPC_SOURCES
  check/symbols.cpp
  check/expressions.cpp
  check/statements.cpp
  check/check_package.cpp
  check/check_atom.cpp
  check/check_connector.cpp
  check/stochastic.cpp
  check/check.cpp)
# Compounds and roots:
list(APPEND BIPC_SOURCES
  check/check_compound.cpp
  check/check_root.cpp)
