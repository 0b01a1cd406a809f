#The SDL - PR reader : constructs, located errors, robustness and the real design files.
list(APPEND TASTE2BIP_TEST_SOURCES
         sdl_structure_test.cpp sdl_transition_test.cpp sdl_errors_test.cpp sdl_real_files_test.cpp)
