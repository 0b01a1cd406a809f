// TASTE names as BIP identifiers: ASN.1 and the interface view allow '-' and names that are BIP
// keywords; a BIP package needs identifiers.
#pragma once

#include <string>
#include <string_view>

namespace smcbip::taste2bip {

/// `name` as a BIP identifier: '-', '.' and spaces become '_', a leading digit gets a '_'
/// before it, and a BIP keyword (`end`, `port`, `data`, ...) gets a '_' after it. Distinct
/// TASTE names may meet (`a-b` and `a_b`); the writer keeps the first and reports the others.
std::string bip_identifier(std::string_view name);

/// `name` folded for matching TASTE names as SDL and the views write them: case ignored, '-' and
/// '_' alike (`Base-commands-Motion2D`, `base_commands_motion2d`).
std::string folded_name(std::string_view name);

}  // namespace smcbip::taste2bip
