#include "taste2bip/asn1/taste_basic_types.h"

namespace smcbip::taste2bip::asn1 {

std::string_view taste_basic_types_text() {
  return "TASTE-BasicTypes DEFINITIONS ::=\n"
         "BEGIN\n"
         "T-Int32 ::= INTEGER (-2147483648 .. 2147483647)\n"
         "T-UInt32 ::= INTEGER (0 .. 4294967295)\n"
         "T-Int8 ::= INTEGER (-128 .. 127)\n"
         "T-UInt8 ::= INTEGER (0 .. 255)\n"
         "T-Boolean ::= BOOLEAN\n"
         "T-Null-Record ::= SEQUENCE {}\n"
         "END\n";
}

}  // namespace smcbip::taste2bip::asn1
