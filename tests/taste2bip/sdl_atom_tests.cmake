# The SDL process as a BIP atom: constructs run by the engines, and the real SDL files.
list(APPEND TASTE2BIP_TEST_SOURCES
  sdl_atom_behaviour_test.cpp
  sdl_atom_timers_test.cpp
  sdl_atom_nested_test.cpp
  sdl_atom_values_test.cpp
  sdl_atom_signature_test.cpp
  sdl_atom_refusals_test.cpp
  sdl_atom_real_files_test.cpp)
