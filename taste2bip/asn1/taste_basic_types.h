// The ASN.1 module TASTE-BasicTypes that the TASTE toolchain supplies to every data view (T-Int32,
// T-UInt32, T-Int8, T-UInt8, T-Boolean, T-Null-Record): designs import it without shipping it.
#pragma once

#include <string_view>

namespace smcbip::taste2bip::asn1 {

inline constexpr std::string_view kTasteBasicTypesModule = "TASTE-BasicTypes";

/// The module's text, read like a data view file when no file given defines it.
std::string_view taste_basic_types_text();

}  // namespace smcbip::taste2bip::asn1
