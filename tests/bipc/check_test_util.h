// Helpers of the checker tests: parse model texts (which must be free of syntax errors) and
// check them, then look for diagnostics.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "bipc/bipc.h"

namespace smcbip::bipc::check_test {

/// A model parsed and checked, with its diagnostics.
struct Checked {
  LoadedModel model;
  Diagnostics diags;
  bool ok = false;

  /// Whether a diagnostic of `severity` at `line` (any line when 0) and `column` (any column
  /// when 0) contains `phrase`.
  bool has(Severity severity, int line, int column, const std::string& phrase) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.severity == severity && (line == 0 || static_cast<int>(d.location.line) == line) &&
          (column == 0 || static_cast<int>(d.location.column) == column) &&
          d.message.find(phrase) != std::string::npos) {
        return true;
      }
    }
    return false;
  }
  /// Whether an error at `line` and `column` (any when 0) contains `phrase`.
  bool has(int line, int column, const std::string& phrase) const {
    return has(Severity::Error, line, column, phrase);
  }
  std::string text() const { return diags.format(model.files); }
};

/// Parses `text` as file `file_name` into `c`'s model, using the packages parsed before it; it
/// becomes the main package.
inline void add_package(Checked& c, const std::string& text, const std::string& file_name) {
  const std::uint32_t file = c.model.files.add(file_name);
  std::unique_ptr<ast::Package> package = parse_package(text, file, c.diags);
  EXPECT_FALSE(c.diags.has_errors()) << c.diags.format(c.model.files);
  for (const auto& used : c.model.packages) package->used_packages.push_back(used.get());
  c.model.main = package.get();
  c.model.packages.push_back(std::move(package));
}

/// Parses one package into `c` and checks it.
inline void check_into(Checked& c, const std::string& text) {
  add_package(c, text, "test.bip");
  c.ok = check(c.model, c.diags);
}

/// Parses one package and checks it.
inline Checked check_text(const std::string& text) {
  Checked c;
  check_into(c, text);
  return c;
}

/// Parses packages (each using the ones before it) and checks them together.
inline Checked check_texts(const std::vector<std::string>& texts) {
  Checked c;
  for (const std::string& text : texts) {
    add_package(c, text, "test" + std::to_string(c.model.packages.size()));
  }
  c.ok = check(c.model, c.diags);
  return c;
}

}  // namespace smcbip::bipc::check_test
