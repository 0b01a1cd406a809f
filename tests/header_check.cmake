# smcbip_header_check(NAME HEADERS <header>... LIBRARIES <target>...): an object library NAME
# with one translation unit per header that includes only it, so that every public header
# compiles on its own.
# With SMCBIP_HEADER_CHECKS off (the sanitizer stage of CI, which would only compile them again)
# nothing is added.
function(smcbip_header_check name)
  if(NOT SMCBIP_HEADER_CHECKS)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "HEADERS;LIBRARIES")
  set(units)
  foreach(header IN LISTS arg_HEADERS)
    string(MAKE_C_IDENTIFIER ${header} unit_name)
    set(unit ${CMAKE_CURRENT_BINARY_DIR}/header_check/${unit_name}.cpp)
    file(CONFIGURE OUTPUT ${unit} CONTENT "#include \"${header}\"\n")
    list(APPEND units ${unit})
  endforeach()
  add_library(${name} OBJECT ${units})
  target_link_libraries(${name} PRIVATE ${arg_LIBRARIES} smcbip_warnings)
endfunction()
