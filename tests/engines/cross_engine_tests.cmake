# Engines cross-run on the same seed: the optimised scheduler's traces against the reference
# engine's (uses the trace harness of conformance_tests.cmake and the generator's models).
list(APPEND ENGINES_TEST_SOURCES cross_engine_test.cpp)
# The optimised scheduler's counted items against the list the reference engine builds.
list(APPEND ENGINES_TEST_SOURCES item_index_test.cpp enabled_positions_test.cpp)
# The in-place copies a run's start restores with.
list(APPEND ENGINES_TEST_SOURCES copy_over_test.cpp)
