# The BIP conformance suite (bip-conformance/EXPECTED.md) and its trace-oracle helpers: quick
# oracles join the engines test executable; wall-clock ones form their own, labelled `slow`.
list(APPEND ENGINES_TEST_SOURCES
  conformance_test.cpp
  conformance_externs.cpp
  trace_oracles.cpp
  trace_oracles_test.cpp)
set(ENGINES_REALTIME_TEST_SOURCES
  conformance_realtime_test.cpp
  conformance_externs.cpp
  trace_oracles.cpp)
list(APPEND ENGINES_TEST_SOURCES extern_ports_test.cpp)
list(APPEND ENGINES_TEST_SOURCES interactive_test.cpp)
