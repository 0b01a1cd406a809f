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
  conformance_externs.cpp
  trace_oracles.cpp
  trace_oracles_test.cpp)
set(ENGINES_REALTIME_TEST_SOURCES
  conformance_realtime_test.cpp
  conformance_externs.cpp
  trace_oracles.cpp)
list(APPEND ENGINES_TEST_SOURCES extern_ports_test.cpp)
list(APPEND ENGINES_TEST_SOURCES explore_test.cpp interactive_test.cpp)
list(APPEND ENGINES_TEST_SOURCES limits_test.cpp maximal_interaction_test.cpp
  model_interface_test.cpp)
