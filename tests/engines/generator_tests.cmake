# The random model generator (for cross-running engines on the same seed) and its test. The
# generator is in three parts: the package and compounds, atom types, connectors and priorities.
set(RANDOM_MODEL_SOURCES random_model.cpp random_model_atoms.cpp random_model_connectors.cpp)
list(APPEND ENGINES_TEST_SOURCES ${RANDOM_MODEL_SOURCES} random_model_test.cpp)

# random_bip_model SEED [--atoms N] [--clocks] ... > out.bip: reproduces a failing seed.
list(TRANSFORM RANDOM_MODEL_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
add_executable(random_bip_model ${CMAKE_CURRENT_LIST_DIR}/random_model_main.cpp
                                ${RANDOM_MODEL_SOURCES})
target_link_libraries(random_bip_model PRIVATE CLI11::CLI11 smcbip_warnings)
