# Registers the self-describing golden models and the conformance run of bipc as CTests.
# Included from tests/bipc/CMakeLists.txt.

# The executable is target 'bipc_tool' (output name bipc); 'bipc' alone is the library.
if(TARGET bipc_tool)
  set(BIPC_TOOL_TARGET bipc_tool)
else()
  set(BIPC_TOOL_TARGET bipc)
endif()
set(BIPC_TOOL_DIR $<TARGET_FILE_DIR:${BIPC_TOOL_TARGET}>)
set(BIPC_GOLDEN_RUNNER ${CMAKE_CURRENT_SOURCE_DIR}/../run_golden.sh)

file(GLOB BIPC_GOLDEN_MODELS CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/golden/invalid/*.bip
  ${CMAKE_CURRENT_SOURCE_DIR}/golden/valid/*.bip
  ${CMAKE_CURRENT_SOURCE_DIR}/golden/tools/*.bip)

foreach(golden_model IN LISTS BIPC_GOLDEN_MODELS)
  get_filename_component(golden_stem ${golden_model} NAME_WLE)
  add_test(NAME bipc.golden.${golden_stem}
    COMMAND bash ${BIPC_GOLDEN_RUNNER} ${BIPC_TOOL_DIR} ${golden_model})
  set_tests_properties(bipc.golden.${golden_stem} PROPERTIES LABELS quick)
endforeach()

# Every reference conformance model and the ESROCOS watchdog model must pass 'bipc check'.
# Exits 77 (skipped) when the shared data set is not next to the repository.
add_test(NAME bipc.conformance
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/conformance.sh ${BIPC_TOOL_DIR})
set_tests_properties(bipc.conformance PROPERTIES LABELS quick SKIP_RETURN_CODE 77)
