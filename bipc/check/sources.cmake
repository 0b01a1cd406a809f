# Checker sources. Core (symbols, expressions, atoms, connectors, driver):
list(APPEND BIPC_SOURCES
  check/symbols.cpp
  check/value_types.cpp
  check/name_scope.cpp
  check/names.cpp
  check/expressions.cpp
  check/clock_constraints.cpp
  check/calls.cpp
  check/statements.cpp
  check/declarations.cpp
  check/annotations.cpp
  check/check_package.cpp
  check/check_atom.cpp
  check/atom_priorities.cpp
  check/atom_determinism.cpp
  check/guard_exclusion.cpp
  check/stochastic.cpp
  check/check_connector.cpp
  check/connector_define.cpp
  check/component_interface.cpp
  check/check.cpp)
# Compounds and roots:
list(APPEND BIPC_SOURCES
  check/check_compound.cpp
  check/check_compound_connectors.cpp
  check/check_compound_priorities.cpp
  check/check_compound_exports.cpp
  check/check_compound_recursion.cpp
  check/check_compound_graph.cpp
  check/check_root.cpp)
