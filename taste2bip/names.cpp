#include "taste2bip/names.h"

#include <cctype>

#include "bipc/bipc.h"

namespace smcbip::taste2bip {

namespace {

bool is_identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

std::string bip_identifier(std::string_view name) {
  std::string out;
  out.reserve(name.size() + 2);
  for (char c : name) out += is_identifier_char(c) ? c : '_';
  if (out.empty() || (out.front() >= '0' && out.front() <= '9')) out.insert(out.begin(), '_');
  if (bipc::is_keyword(out)) out += '_';
  return out;
}

std::string folded_name(std::string_view name) {
  std::string out;
  for (char c : name) {
    out += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace smcbip::taste2bip
