// C++ generation from a checked system: its code as straight C++ behind the engines' ModelCode
// interface, so that the engines run it compiled instead of interpreted.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::codegen {

struct GenerateOptions {
  /// The C++ namespace of the generated code (`a::b` allowed): several generated models can be
  /// linked into one program.
  std::string name_space = "bip_model";
};

struct GeneratedFile {
  std::string name;  // relative to the output folder
  std::string text;
};

/// The text opening namespace `name_space` (a path), and the matching closing text.
std::pair<std::string, std::string> namespace_lines(const std::string& name_space);

/// Whether `name_space` is a valid C++ namespace path (identifiers joined by `::`, no reserved
/// identifiers); otherwise says why in `error`.
bool valid_namespace(const std::string& name_space, std::string& error);

/// `model_code.h` and `model_code.cpp`: in namespace `options.name_space`, the function
///   std::unique_ptr<smcbip::engines::ModelCode> make_model_code(
///       const smcbip::bipc::ir::System&, const smcbip::engines::BoundFunctions&,
///       smcbip::engines::CallContext&, const smcbip::engines::GuardBounds*)
/// (the engines' CompiledModel::CodeFactory) whose ModelCode evaluates and executes every Code
/// of `system` as compiled C++, found by Code::id. Guards over clocks find their dates through
/// the engines' ClockBounds and time sets. The code must run with the same System (the same
/// numbering of its Code); throws UntranslatableCode on code that was not checked.
std::vector<GeneratedFile> generate_cpp(const ir::System& system, const GenerateOptions& options);

}  // namespace smcbip::bipc::codegen
