# C++ generation from the IR (bipc gen).
list(APPEND BIPC_SOURCES
  codegen/atom_steps.cpp
  codegen/code_cpp.cpp
  codegen/generate_cpp.cpp
  codegen/generate_project.cpp)
