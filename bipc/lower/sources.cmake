# Lowering of a checked root to the IR, and the IR's JSON and Graphviz views.
list(APPEND BIPC_SOURCES
  lower/compile_code.cpp
  lower/lower_types.cpp
  lower/instantiate.cpp
  ir/ir_json.cpp
  ir/ir_dot.cpp)
