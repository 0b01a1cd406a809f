# Unit tests of the stochastic area of the engines: random streams and firing-date distributions.
list(APPEND ENGINES_TEST_SOURCES distributions_test.cpp)
list(APPEND ENGINES_TEST_SOURCES stochastic_engine_test.cpp)
