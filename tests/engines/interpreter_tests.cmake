# Unit tests of the interpreter: guards over clocks read as clock bounds.
list(APPEND ENGINES_TEST_SOURCES clock_bounds_test.cpp)
