// Helpers of the ASN.1 data view tests: read text into a view and show its diagnostics.
#pragma once

#include <string>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"

namespace smcbip::taste2bip::asn1::testing {

/// A data view read from source texts (file i is `t<i>.asn`), with its diagnostics.
struct Read {
  DataView view;
  bipc::Diagnostics diags;
  bipc::SourceFiles files;

  /// Reads `text` as the next file.
  Read& add(const std::string& text) {
    std::uint32_t file = files.add("t" + std::to_string(files.paths.size()) + ".asn");
    read_asn1(text, file, view, diags);
    return *this;
  }
  Read& resolved() {
    resolve(view, diags);
    return *this;
  }
  std::string errors() const { return diags.format(files); }
  /// The type assigned to `name` in any module (the test fails on a null dereference otherwise).
  const Type* type(const std::string& name) const {
    auto id = view.find_type(name);
    return id ? &view.type(*id)->type : nullptr;
  }
};

/// A module `M` around `body`.
inline std::string module(const std::string& body) {
  return "M DEFINITIONS AUTOMATIC TAGS ::= BEGIN\n" + body + "\nEND\n";
}

}  // namespace smcbip::taste2bip::asn1::testing
