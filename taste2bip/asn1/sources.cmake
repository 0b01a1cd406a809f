# The ASN.1 data view: the subset TASTE designs use, read with located diagnostics.
list(APPEND TASTE2BIP_SOURCES
  asn1/lexer.cpp
  asn1/parser.cpp
  asn1/parser_type.cpp
  asn1/data_view.cpp
  asn1/resolve.cpp
  asn1/taste_basic_types.cpp)
