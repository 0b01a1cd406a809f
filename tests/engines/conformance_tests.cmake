# The BIP conformance suite (bip-conformance/EXPECTED.md) and its trace-oracle helpers: quick
# oracles join the engines test executable, one file per EXPECTED.md section or theme; wall-clock
# ones form their own, labelled `slow`.
list(APPEND ENGINES_TEST_SOURCES
  conformance_suite.cpp
  conformance_timed_test.cpp
  conformance_structure_test.cpp
  conformance_connectors_test.cpp
  conformance_priorities_test.cpp
  conformance_multithread_suite_test.cpp
  conformance_hand_derived_test.cpp
  trace_oracles_test.cpp)
set(ENGINES_REALTIME_TEST_SOURCES conformance_realtime_test.cpp)
# The trace oracles and the conformance suite's externs, compiled once for the three test
# executables that use them.
add_library(engines_test_support STATIC trace_oracles.cpp conformance_externs.cpp)
target_link_libraries(engines_test_support PUBLIC engines GTest::gtest PRIVATE smcbip_warnings)
target_compile_definitions(engines_test_support PRIVATE SMCBIP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
list(APPEND ENGINES_TEST_SOURCES extern_ports_test.cpp builtins_test.cpp)
list(APPEND ENGINES_TEST_SOURCES explore_test.cpp interactive_test.cpp replay_test.cpp)
list(APPEND ENGINES_TEST_SOURCES limits_test.cpp maximal_interaction_test.cpp
  model_interface_test.cpp)

# The conformance models as generated C++ (bipc gen), for the suite's generated-model variants:
# generated at build time into a few shares compiled in parallel, with their table.
set(GENERATED_CONFORMANCE_DIR "${CMAKE_CURRENT_BINARY_DIR}/generated_conformance")
set(GENERATED_CONFORMANCE_CHUNKS 4)
set(generated_conformance_outputs "${GENERATED_CONFORMANCE_DIR}/registry.cpp")
math(EXPR last_chunk "${GENERATED_CONFORMANCE_CHUNKS} - 1")
foreach(k RANGE ${last_chunk})
  list(APPEND generated_conformance_outputs "${GENERATED_CONFORMANCE_DIR}/chunk_${k}.cpp")
endforeach()
add_custom_command(
  OUTPUT ${generated_conformance_outputs}
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/generate_conformance.sh" $<TARGET_FILE_DIR:bipc_tool>
          "${GENERATED_CONFORMANCE_DIR}" ${GENERATED_CONFORMANCE_CHUNKS}
  DEPENDS bipc_tool "${CMAKE_CURRENT_SOURCE_DIR}/generate_conformance.sh"
          "${PROJECT_SOURCE_DIR}/tests/bipc/conformance.sh"
  COMMENT "bipc gen over the conformance models"
  VERBATIM)
add_library(generated_conformance STATIC ${generated_conformance_outputs})
target_link_libraries(generated_conformance PUBLIC engines PRIVATE smcbip_warnings)
