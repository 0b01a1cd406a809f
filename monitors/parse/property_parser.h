// Reading property files (PROPERTIES.md): queries, declarations and path formulas, with
// `file:line:column` diagnostics for what is not one.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors {

/// A property file as read: its declarations and queries when there was no error, and the
/// diagnostics (the parser prints nothing).
struct ParsedProperties {
  PropertyFile file;
  bipc::SourceFiles sources;
  bipc::Diagnostics diagnostics;

  bool ok() const { return !diagnostics.has_errors(); }
};

/// Parses `text`, read from `path` (which only names it in diagnostics). Beyond the grammar it
/// checks what needs no model: constants and parameters declared once and before use in bounds,
/// thresholds and run counts; thresholds in [0, 1]; step bounds and run counts whole numbers;
/// interval bounds in order. Names inside atomic predicates are resolved against a model later.
/// `parameters` are parameters given on the command line, `NAME=start:stop:step` or
/// `NAME={v1,v2,...}`: each replaces the file's declaration of NAME, or declares it before the
/// file's first line; their errors are reported in a source named `--param`.
ParsedProperties parse_properties(std::string_view text, const std::string& path,
                                  const std::vector<std::string>& parameters = {});

/// Reads the file at `path` and parses it; a file that cannot be read is an error at 0:0.
ParsedProperties load_properties(const std::string& path,
                                 const std::vector<std::string>& parameters = {});

}  // namespace smcbip::monitors
