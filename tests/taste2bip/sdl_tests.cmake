# The SDL-PR reader: constructs, located errors, robustness and the real design files.
list(APPEND TASTE2BIP_TEST_SOURCES
  sdl_real_files_test.cpp)
