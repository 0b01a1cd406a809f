# Unit tests of the stochastic area of the engines: random streams and firing-date distributions,
# and the distribution of the scheduler's choice on untimed models.
list(APPEND ENGINES_TEST_SOURCES distributions_test.cpp)
list(APPEND ENGINES_TEST_SOURCES stochastic_engine_test.cpp)
# The stochastic race of the compiled step path on lazy models, against the scheduler's.
list(APPEND ENGINES_TEST_SOURCES lazy_race_test.cpp)
# The clock arithmetic of the draws.
list(APPEND ENGINES_TEST_SOURCES clock_dates_test.cpp)
list(APPEND ENGINES_TEST_SOURCES shared_window_choice_test.cpp)
