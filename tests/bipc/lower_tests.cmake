# Tests of the lowering to the IR (instantiation, code) and of the IR's JSON and Graphviz views.
list(APPEND BIPC_TEST_SOURCES
  lower_instantiate_test.cpp
  lower_code_test.cpp
  lower_views_test.cpp
  lower_scaling_test.cpp)
