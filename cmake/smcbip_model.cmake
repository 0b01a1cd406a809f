# smcbip_add_model(<target> MODEL <file.bip> ROOT <root> [NAMESPACE <ns>]
#                  [INCLUDE_DIRS <dir>...] [EXTERN_SOURCES <name>...] [DEPENDS <file>...])
#
# Generates the C++ of a BIP model at build time (`bipc gen --no-main`, into
# ${CMAKE_CURRENT_BINARY_DIR}/<target>) and compiles it into the static library <target>, whose
# users include "model.h" (namespace <ns>, default <target>): the model, its identity and the
# Component a host program drives. INCLUDE_DIRS are bipc's -I folders; EXTERN_SOURCES the file
# names of the model's @cpp sources, which bipc gen copies under extern/ and which are compiled
# in; DEPENDS the files besides MODEL (used packages, extern C++) whose change regenerates it.
# Works in smcbip's own build and after find_package(smcbip).
function(smcbip_add_model target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "MODEL;ROOT;NAMESPACE"
                        "INCLUDE_DIRS;EXTERN_SOURCES;DEPENDS")
  if(NOT arg_MODEL OR NOT arg_ROOT)
    message(FATAL_ERROR "smcbip_add_model(${target}): MODEL and ROOT are required")
  endif()
  if(NOT arg_NAMESPACE)
    set(arg_NAMESPACE ${target})
  endif()
  if(TARGET bipc_tool)
    set(bipc bipc_tool)
    set(engines engines)
  else()
    set(bipc smcbip::bipc_tool)
    set(engines smcbip::engines)
  endif()
  get_filename_component(model "${arg_MODEL}" ABSOLUTE)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  set(sources "${out}/model_code.cpp" "${out}/model_data.cpp" "${out}/model_externs.cpp")
  foreach(source IN LISTS arg_EXTERN_SOURCES)
    list(APPEND sources "${out}/extern/${source}")
  endforeach()
  set(includes)
  foreach(dir IN LISTS arg_INCLUDE_DIRS)
    get_filename_component(dir "${dir}" ABSOLUTE)
    list(APPEND includes -I "${dir}")
  endforeach()
  add_custom_command(
    OUTPUT ${sources} "${out}/model.h" "${out}/model_code.h"
    COMMAND ${bipc} gen "${model}" --root "${arg_ROOT}" -o "${out}" --namespace "${arg_NAMESPACE}"
            --no-main ${includes}
    DEPENDS ${bipc} "${model}" ${arg_DEPENDS}
    COMMENT "bipc gen ${arg_MODEL}"
    VERBATIM)
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC "${out}" PRIVATE "${out}/extern")
  target_link_libraries(${target} PUBLIC ${engines})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
