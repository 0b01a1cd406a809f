# The IR: its helpers, its views (outline, JSON, Graphviz), its full data encoding and the
# model hash.
list(APPEND BIPC_SOURCES
  ir/ir.cpp
  ir/clock_guard.cpp
  ir/data_guard.cpp
  ir/simple_action.cpp
  ir/state_change.cpp
  ir/ir_json.cpp
  ir/ir_text.cpp
  ir/ir_dot.cpp
  ir/ir_data_write.cpp
  ir/ir_data_read.cpp
  ir/detail/ir_data_reader.cpp
  ir/ir_data_check.cpp
  ir/ir_data_bytes.cpp
  ir/model_hash.cpp
  ir/detail/sha256.cpp)
