# The random model generator (for cross-running engines on the same seed) and its test.
list(APPEND ENGINES_TEST_SOURCES random_model.cpp random_model_test.cpp)

# random_bip_model SEED [--atoms N] [--clocks] ... > out.bip: reproduces a failing seed.
add_executable(random_bip_model ${CMAKE_CURRENT_LIST_DIR}/random_model_main.cpp
                                ${CMAKE_CURRENT_LIST_DIR}/random_model.cpp)
target_link_libraries(random_bip_model PRIVATE CLI11::CLI11 smcbip_warnings)
