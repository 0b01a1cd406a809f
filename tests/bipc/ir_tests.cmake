# Tests of the IR's full data encoding (round trips, hostile input), of the model hash and of
# what a transition's code tells of its firing.
list(APPEND BIPC_TEST_SOURCES
  ir_data_test_util.cpp
  ir_data_fields_test.cpp
  ir_data_corpus_test.cpp
  ir_data_robust_test.cpp
  model_hash_test.cpp
  state_change_test.cpp)
