# The ESROCOS watchdog: the original BIP run here, and compared with the translation.
list(APPEND TASTE2BIP_TEST_SOURCES watchdog_model.cpp watchdog_untimed.cpp watchdog_traces.cpp
  watchdog_translation.cpp watchdog_run_test.cpp watchdog_untimed_test.cpp watchdog_traces_test.cpp
  watchdog_answers.cpp watchdog_properties_test.cpp watchdog_compare_test.cpp
  watchdog_timed_compare_test.cpp watchdog_same_answers_test.cpp)
# The same nominal properties through the command line (taste2bip --atom, then smcbip check).
add_test(NAME taste2bip.watchdog_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/watchdog_cli.sh
  $<TARGET_FILE_DIR:taste2bip_tool> ${PROJECT_SOURCE_DIR})
set_tests_properties(taste2bip.watchdog_cli PROPERTIES LABELS quick SKIP_RETURN_CODE 77)
