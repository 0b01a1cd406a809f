# The host-driven Execution against Simulator runs, and its steps' allocations: the latter
# replaces the global operator new, so it is an executable of its own.
list(APPEND ENGINES_TEST_SOURCES execution_test.cpp)

add_executable(engines_allocation_tests ${CMAKE_CURRENT_LIST_DIR}/execution_allocation_test.cpp)
target_link_libraries(engines_allocation_tests PRIVATE engines_test_support generated_conformance
                      GTest::gtest_main smcbip_warnings)
target_compile_definitions(engines_allocation_tests PRIVATE
  SMCBIP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(engines_allocation_tests PROPERTIES LABELS quick DISCOVERY_TIMEOUT 60)
