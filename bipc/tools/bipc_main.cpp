// bipc: check BIP2 models, draw their architecture, dump their IR, generate C++.
//
// Exit codes: 0 success, 2 input or usage error, 3 internal error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "bipc/bipc.h"
#include "bipc/codegen/code_cpp.h"
#include "bipc/codegen/generate_cpp.h"
#include "bipc/codegen/generate_project.h"
#include "bipc/exit_codes.h"
#include "bipc/input_file.h"
#include "bipc/ir/ir_dot.h"
#include "bipc/ir/ir_json.h"
#include "bipc/ir/ir_text.h"
#include "bipc/ir/model_hash.h"
#include "bipc/json_dump.h"
#include "bipc/options.h"
#include "bipc/output_file.h"
#include "bipc/tool_main.h"

namespace {

using namespace smcbip::bipc;
using smcbip::exit_codes::kInputError;
using smcbip::exit_codes::kInternalError;
constexpr int kOk = smcbip::exit_codes::kSuccess;

/// Prints the diagnostics of a run and tells whether it may go on.
bool report(const FrontendResult& result) {
  Diagnostics sorted = result.diags;
  sorted.sort_by_location();
  std::cerr << sorted.format(result.model.files);
  return !result.diags.has_errors();
}

/// The front end's run on the model file, which must be a regular file when it exists.
FrontendResult load(const FrontendOptions& options, bool need_system) {
  require_model_file(options.file);
  return run_frontend(options, need_system);
}

int run_check(const FrontendOptions& options) {
  FrontendResult result = load(options, /*need_system=*/false);
  return report(result) ? kOk : kInputError;
}

int run_dot(const FrontendOptions& options, const std::string& output) {
  FrontendResult result = load(options, /*need_system=*/true);
  if (!report(result) || !result.system) return kInputError;
  const std::string dot = ir::to_dot(*result.system);
  if (output.empty() || output == "-") {
    std::cout << dot;
    return kOk;
  }
  std::string error, target;
  if (!output_target(output, target, error) || !ir::render_svg(dot, target, error)) {
    std::cerr << "bipc: error: " << error << "\n";
    return kInputError;
  }
  return kOk;
}

int run_ir(const FrontendOptions& options, const std::string& output, bool json_format) {
  FrontendResult result = load(options, /*need_system=*/true);
  if (!report(result) || !result.system) return kInputError;
  const std::string json =
      json_format ? dump_json(ir::to_json(*result.system), 2) + "\n" : ir::to_text(*result.system);
  if (output.empty() || output == "-") {
    std::cout << json;
    return kOk;
  }
  std::string error;
  if (!write_file_atomically(output, json, error)) {
    std::cerr << "bipc: error: " << error << "\n";
    return kInputError;
  }
  return kOk;
}

/// Writes every file into `folder` (created if needed); each goes through a temporary file, and
/// none is renamed into place before all were written.
int run_hash(const FrontendOptions& options) {
  FrontendResult result = load(options, /*need_system=*/true);
  if (!report(result) || !result.system) return kInputError;
  // An extern source that cannot be read throws ExternSourceError, an InputError.
  std::cout << ir::model_hash(*result.system,
                              ir::extern_sources_of(*result.system, options.include_dirs))
            << "\n";
  return kOk;
}

int run_gen(const FrontendOptions& options, const std::string& output,
            codegen::ProjectOptions project, bool code_only) {
  std::string error;
  if (!codegen::valid_namespace(project.code.name_space, error)) {
    std::cerr << "bipc: error: --namespace: " << error << "\n";
    return kInputError;
  }
  FrontendResult result = load(options, /*need_system=*/true);
  if (!report(result) || !result.system) return kInputError;
  std::vector<codegen::GeneratedFile> files;
  if (!code_only) {
    project.extern_sources = ir::extern_sources_of(*result.system, options.include_dirs);
  }
  project.model_file = options.file;
  project.root = options.root.empty() ? result.system->root_type : options.root;
  project.smcbip_version = SMCBIP_VERSION_TEXT;
  try {
    files = code_only ? codegen::generate_cpp(*result.system, project.code)
                      : codegen::generate_project(*result.system, project);
  } catch (const codegen::ExternSourceClash& clash) {
    std::cerr << "bipc: error: " << clash.message << "\n";
    return kInputError;
  } catch (const codegen::UntranslatableCode& untranslatable) {
    std::cerr << "bipc: internal error: " << untranslatable.message << "\n";
    return kInternalError;
  }
  std::vector<NamedText> named;
  for (const codegen::GeneratedFile& file : files) named.push_back({file.name, file.text});
  if (!write_files_atomically(output, named, error)) {
    std::cerr << "bipc: error: " << error << "\n";
    return kInputError;
  }
  return kOk;
}

int run(int argc, char** argv) {
  CLI::App app{"bipc: the BIP2 front end of smcbip (check, draw, dump the IR)"};
  app.require_subcommand(1);

  FrontendOptions check_options;
  CLI::App* check = app.add_subcommand("check", "check a model (and instantiate --root)");
  register_frontend_options(*check, check_options);

  FrontendOptions dot_options;
  std::string dot_output;
  CLI::App* dot = app.add_subcommand("dot", "draw the architecture of a root through Graphviz");
  register_frontend_options(*dot, dot_options);
  dot->add_option("-o,--output", dot_output, "picture file: .svg, .png, .pdf or .dot (- : stdout)");

  FrontendOptions ir_options;
  std::string ir_output;
  bool json = false;
  CLI::App* ir_cmd = app.add_subcommand("ir", "dump the IR of a root instantiation");
  register_frontend_options(*ir_cmd, ir_options);
  ir_cmd->add_flag("--json", json,
                   "the complete IR as JSON (default: an outline of the instances)");
  ir_cmd->add_option("-o,--output", ir_output, "output file (default: stdout)");

  FrontendOptions gen_options;
  std::string gen_output;
  codegen::ProjectOptions gen;
  bool no_main = false, code_only = false;
  CLI::App* gen_cmd = app.add_subcommand("gen", "generate the C++ project of a root instantiation");
  register_frontend_options(*gen_cmd, gen_options);
  gen_cmd->add_option("-o,--output", gen_output, "output folder (created if needed)")->required();
  gen_cmd->add_option("--namespace", gen.code.name_space, "C++ namespace of the generated code")
      ->capture_default_str();
  gen_cmd->add_flag("--no-main", no_main,
                    "a library for a host program (no executable taking smcbip simulate's "
                    "options)");
  gen_cmd->add_flag("--code-only", code_only,
                    "only model_code.h and model_code.cpp, for a program that holds the "
                    "model's IR itself (engines::CompiledModel); extern sources are not read");

  FrontendOptions hash_options;
  CLI::App* hash = app.add_subcommand(
      "hash", "print the model's identity: SHA-256 of its normalised IR and extern sources");
  register_frontend_options(*hash, hash_options);

  smcbip::cli::add_version_flags(app, "bipc");
  if (const int code = smcbip::cli::parse_command_line(app, argc, argv); code >= 0) return code;
  if (check->parsed()) return run_check(check_options);
  if (dot->parsed()) return run_dot(dot_options, dot_output);
  if (gen_cmd->parsed()) {
    gen.main = !no_main;
    return run_gen(gen_options, gen_output, gen, code_only);
  }
  if (hash->parsed()) return run_hash(hash_options);
  return run_ir(ir_options, ir_output, json);
}

}  // namespace

int main(int argc, char** argv) {
  return smcbip::cli::guarded_main("bipc", smcbip::exit_codes::kJudgingCodes,
                                   [&] { return run(argc, argv); });
}
