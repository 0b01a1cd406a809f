# Quick checks of --real-time and --relaxed on small models written in the test: tens of
# milliseconds each and one-sided timing facts, so they join engines_tests (label quick).
list(APPEND ENGINES_TEST_SOURCES realtime_quick_test.cpp)
