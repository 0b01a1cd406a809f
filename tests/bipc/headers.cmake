# Every public header of bipc must compile on its own: one generated translation unit each.
set(BIPC_PUBLIC_HEADERS
  bipc/bipc.h
  bipc/diagnostics.h
  bipc/options.h
  bipc/output_file.h
  bipc/timing.h
  bipc/ast/ast.h
  bipc/ir/ir.h
  bipc/ir/ir_json.h
  bipc/ir/ir_dot.h
  bipc/ir/ir_text.h
  bipc/ir/ir_data.h
  bipc/ir/model_hash.h)
set(BIPC_HEADER_UNITS)
foreach(header IN LISTS BIPC_PUBLIC_HEADERS)
  string(MAKE_C_IDENTIFIER ${header} unit_name)
  set(unit ${CMAKE_CURRENT_BINARY_DIR}/header_check/${unit_name}.cpp)
  file(CONFIGURE OUTPUT ${unit} CONTENT "#include \"${header}\"\n")
  list(APPEND BIPC_HEADER_UNITS ${unit})
endforeach()
add_library(bipc_header_check OBJECT ${BIPC_HEADER_UNITS})
target_link_libraries(bipc_header_check PRIVATE bipc CLI11::CLI11 smcbip_warnings)
