# Lowering of a checked root to the IR.
list(APPEND BIPC_SOURCES
  lower/compile_code.cpp
  lower/const_eval.cpp
  lower/lower_types.cpp
  lower/lower_atom_type.cpp
  lower/lower_connector_type.cpp
  lower/lower_stochastic.cpp
  lower/instantiate.cpp
  lower/instance_checks.cpp)
