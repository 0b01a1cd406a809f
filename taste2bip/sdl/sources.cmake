# The SDL-PR reader: lexer and recursive-descent parser into the syntax tree of sdl_ast.h.
list(APPEND TASTE2BIP_SOURCES
  sdl/detail/sdl_lexer.cpp
  sdl/detail/sdl_parser.cpp
  sdl/detail/sdl_parser_tokens.cpp
  sdl/detail/sdl_parser_state.cpp
  sdl/detail/sdl_parser_transition.cpp
  sdl/detail/sdl_parser_expr.cpp)
