# The SDL process as a BIP atom (sdl_atom.h).
list(APPEND TASTE2BIP_SOURCES
  translate/sdl_atom.cpp
  translate/sdl_atom_actions.cpp
  translate/sdl_atom_assign.cpp
  translate/sdl_atom_builtins.cpp
  translate/sdl_atom_calls.cpp
  translate/sdl_atom_data.cpp
  translate/sdl_atom_decision.cpp
  translate/sdl_atom_expr.cpp
  translate/sdl_atom_inputs.cpp
  translate/sdl_atom_loops.cpp
  translate/sdl_atom_nested.cpp
  translate/sdl_atom_signature.cpp
  translate/sdl_atom_states.cpp
  translate/sdl_atom_steps.cpp)
