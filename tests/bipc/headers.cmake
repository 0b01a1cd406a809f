# Every public header of bipc must compile on its own: one generated translation unit each.
set(BIPC_PUBLIC_HEADERS
  bipc/bipc.h
  bipc/diagnostics.h
  bipc/options.h
  bipc/output_file.h
  bipc/utf8.h
  bipc/input_file.h
  bipc/errors.h
  bipc/exit_codes.h
  bipc/tool_main.h
  bipc/timing.h
  bipc/ast/ast.h
  bipc/ir/ir.h
  bipc/ir/ir_json.h
  bipc/ir/ir_dot.h
  bipc/ir/ir_text.h
  bipc/ir/ir_data.h
  bipc/ir/model_hash.h)
smcbip_header_check(bipc_header_check HEADERS ${BIPC_PUBLIC_HEADERS}
  LIBRARIES bipc CLI11::CLI11)
