# The ESROCOS watchdog: the original BIP run here, and compared with the translation.
list(APPEND TASTE2BIP_TEST_SOURCES watchdog_model.cpp watchdog_untimed.cpp watchdog_traces.cpp
  watchdog_translation.cpp watchdog_run_test.cpp watchdog_untimed_test.cpp watchdog_traces_test.cpp
  watchdog_answers.cpp watchdog_properties_test.cpp watchdog_compare_test.cpp
  watchdog_timed_compare_test.cpp watchdog_same_answers_test.cpp)
