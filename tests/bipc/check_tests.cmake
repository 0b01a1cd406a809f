# Unit tests of the checker.
list(APPEND BIPC_TEST_SOURCES
  check_package_test.cpp
  check_expressions_test.cpp
  check_atom_test.cpp
  check_determinism_test.cpp
  check_connector_test.cpp)
list(APPEND BIPC_TEST_SOURCES check_compound_test.cpp)
list(APPEND BIPC_TEST_SOURCES limits_test.cpp)
