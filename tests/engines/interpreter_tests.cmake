# Unit tests of the interpreter: guards over clocks read as clock bounds.
list(APPEND ENGINES_TEST_SOURCES clock_bounds_test.cpp)
# Guards led by an integer comparison, tested before (or instead of) interpreting them.
list(APPEND ENGINES_TEST_SOURCES leading_comparison_test.cpp value_dispatch_test.cpp)
# The offers of atoms guarded by those comparisons alone, kept by the values they read.
list(APPEND ENGINES_TEST_SOURCES offer_memo_test.cpp)
# Actions of plain assignments, run straight on the slots.
list(APPEND ENGINES_TEST_SOURCES simple_action_test.cpp)
# Transitions said always to change their atom, fired by the interpreter from enabled states.
list(APPEND ENGINES_TEST_SOURCES state_change_semantics_test.cpp)
# Faults of the model's code at run time, reported at their place in the model.
list(APPEND ENGINES_TEST_SOURCES model_faults_test.cpp)
