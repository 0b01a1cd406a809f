# Tests of the IR's full data encoding (round trips, hostile input) and of the model hash.
list(APPEND BIPC_TEST_SOURCES
  ir_data_test_util.cpp
  ir_data_fields_test.cpp
  ir_data_corpus_test.cpp
  ir_data_robust_test.cpp
  model_hash_test.cpp)
