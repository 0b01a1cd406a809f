// The IR's data encoding as CBOR bytes (ir_data.h), with the decoder's guards against hostile
// input that nlohmann's CBOR reader does not have itself.
#include <string>

#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir {

using nlohmann::json;

namespace {

/// The deepest nesting of arrays and maps from_data can need: a define node is an object
/// holding an array of nodes (two levels each) below five levels of System, connector type
/// and define list, with room to spare.
constexpr std::size_t kMaxCborNesting = 2 * kMaxDefineDepth + 16;

/// A first SAX pass over the bytes that builds nothing: nlohmann's CBOR reader recurses once per
/// level of nesting, so bytes that open arrays by the million would overflow the stack before
/// from_data could look at them. Refusing to open one level too many stops the reader there.
class NestingLimit {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(number_integer_t) { return true; }
  bool number_unsigned(number_unsigned_t) { return true; }
  bool number_float(number_float_t, const string_t&) { return true; }
  bool string(string_t&) { return true; }
  bool binary(binary_t&) { return true; }
  bool key(string_t&) { return true; }
  bool start_object(std::size_t) { return open(); }
  bool start_array(std::size_t) { return open(); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t, const std::string&, const json::exception& e) {
    error_ = e.what();
    return false;
  }

  /// Why the pass stopped; called when sax_parse returned false.
  const std::string& error() const { return error_; }

 private:
  bool open() {
    if (++depth_ <= kMaxCborNesting) return true;
    error_ = "arrays and maps nested more than " + std::to_string(kMaxCborNesting) + " deep";
    return false;
  }
  bool close() {
    --depth_;
    return true;
  }

  std::size_t depth_ = 0;
  std::string error_;
};

}  // namespace

std::vector<std::uint8_t> to_bytes(const System& system) { return json::to_cbor(to_data(system)); }

System from_bytes(std::span<const std::uint8_t> bytes) {
  NestingLimit limit;
  if (!json::sax_parse(bytes.begin(), bytes.end(), &limit, json::input_format_t::cbor)) {
    throw IrDataError{"CBOR: " + limit.error()};
  }
  json data;
  try {
    data = json::from_cbor(bytes.begin(), bytes.end());
  } catch (const json::exception& e) {
    throw IrDataError{std::string("CBOR: ") + e.what()};
  }
  return from_data(data);
}

}  // namespace smcbip::bipc::ir
