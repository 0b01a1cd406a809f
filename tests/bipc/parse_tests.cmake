# Unit tests of the parse area (lexer, parser, loader) and the real-model parse check.
list(APPEND BIPC_TEST_SOURCES
  parse_lexer_test.cpp
  parse_parser_test.cpp
  parse_expr_test.cpp
  parse_errors_test.cpp
  parse_loader_test.cpp)
