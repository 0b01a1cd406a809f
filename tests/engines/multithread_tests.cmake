# The multithread scheduler against the reference semantics, its fork-join pool and its
# parallel-safety scan.
list(APPEND ENGINES_TEST_SOURCES multithread_test.cpp)
