// Helpers of the lowering tests: run a model text through parse, check and instantiate.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "bipc/ir/ir_json.h"

namespace smcbip::bipc::lower_test {

/// A model lowered from text; `system` is empty when some stage reported an error.
struct Lowered {
  LoadedModel model;
  Diagnostics diags;
  bool checked = false;  // parse and check passed, so errors come from instantiate
  std::optional<ir::System> system;

  std::string messages() const { return diags.format(model.files); }
  bool has_message(const std::string& part) const {
    return std::any_of(diags.all().begin(), diags.all().end(), [&](const Diagnostic& d) {
      return d.message.find(part) != std::string::npos;
    });
  }
};

/// Parses `text` as one package (no `use`), checks it and instantiates `root`.
inline std::unique_ptr<Lowered> lower_text(const std::string& text, const std::string& root) {
  auto result = std::make_unique<Lowered>();
  const std::uint32_t file = result->model.files.add("test.bip");
  std::unique_ptr<ast::Package> package = parse_package(text, file, result->diags);
  if (!package || result->diags.has_errors()) return result;
  result->model.main = package.get();
  result->model.packages.push_back(std::move(package));
  if (!check(result->model, result->diags)) return result;
  std::optional<ast::ComponentDecl> decl = parse_root(root, file, result->diags);
  if (!decl || !check_root(result->model, *decl, result->diags)) return result;
  result->checked = true;
  result->system = instantiate(result->model, *decl, result->diags);
  return result;
}

/// Like lower_text, but fails the test unless every stage succeeded.
inline std::unique_ptr<Lowered> lower_ok(const std::string& text, const std::string& root) {
  auto result = lower_text(text, root);
  EXPECT_TRUE(result->system.has_value()) << result->messages();
  return result;
}

/// The instructions of some code as the JSON view writes them.
inline std::vector<std::string> code_text(const ir::Code& code, const ir::System& system) {
  std::vector<std::string> texts;
  for (const ir::Instr& in : code.instrs) texts.push_back(ir::instruction_text(in, system));
  return texts;
}

inline const ir::AtomInstance* atom_at(const ir::System& system, const std::string& path) {
  for (const ir::AtomInstance& a : system.atoms) {
    if (a.path == path) return &a;
  }
  return nullptr;
}

inline ir::Index atom_index(const ir::System& system, const std::string& path) {
  for (ir::Index i = 0; i < system.atoms.size(); ++i) {
    if (system.atoms[i].path == path) return i;
  }
  return ir::kNone;
}

inline ir::Index connector_index(const ir::System& system, const std::string& path) {
  for (ir::Index i = 0; i < system.connectors.size(); ++i) {
    if (system.connectors[i].path == path) return i;
  }
  return ir::kNone;
}

inline ir::Index port_index(const ir::System& system, const std::string& atom_path,
                            const std::string& port) {
  const ir::AtomInstance* atom = atom_at(system, atom_path);
  if (atom == nullptr) return ir::kNone;
  const auto& ports = system.atom_types[atom->type].ports;
  for (ir::Index i = 0; i < ports.size(); ++i) {
    if (ports[i].name == port) return i;
  }
  return ir::kNone;
}

/// The PortRef of `atom_path.port` (an internal port of an atom instance).
inline ir::PortRef atom_port(const ir::System& system, const std::string& atom_path,
                             const std::string& port) {
  return {ir::PortRef::Kind::Atom, atom_index(system, atom_path),
          port_index(system, atom_path, port)};
}

inline const ir::AtomType& atom_type_of(const ir::System& system, const std::string& path) {
  return system.atom_types.at(atom_at(system, path)->type);
}

}  // namespace smcbip::bipc::lower_test
