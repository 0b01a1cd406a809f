# smcbip_header_check(NAME HEADERS <header>... LIBRARIES <target>...): an object library NAME
# with one translation unit per header that includes only it, so that every public header
# compiles on its own.
function(smcbip_header_check name)
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
