# The parse area of bipc: lexer, recursive-descent parser and package loader.
list(APPEND BIPC_SOURCES
  parse/token.cpp
  parse/lexer.cpp
  parse/parser.cpp
  parse/parser_package.cpp
  parse/parser_atom.cpp
  parse/parser_connector_compound.cpp
  parse/parser_expr.cpp
  parse/loader.cpp)
