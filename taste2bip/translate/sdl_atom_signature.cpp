// The signature of a process inside an SDL system, read from the signals its channels and
// signal routes carry to and from the environment.
#include <algorithm>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"
#include "taste2bip/translate/sdl_atom.h"

namespace smcbip::taste2bip {

namespace {

using detail::folded;

/// The blocks from the system down to the one declaring `process` (empty when none does).
bool block_path(const std::vector<sdl::Block>& blocks, const std::string& process,
                std::vector<const sdl::Block*>& path) {
  for (const sdl::Block& b : blocks) {
    path.push_back(&b);
    const bool here = std::any_of(b.processes.begin(), b.processes.end(),
                                  [&](const auto& p) { return folded(p.name) == folded(process); });
    if (here || block_path(b.blocks, process, path)) return true;
    path.pop_back();
  }
  return false;
}

/// Adds the signals of `channels` between the environment and one of `ends`.
void add_paths(const std::vector<sdl::Channel>& channels, const std::vector<std::string>& ends,
               std::vector<std::string>& in, std::vector<std::string>& out) {
  auto is_end = [&](const std::string& n) {
    return std::find(ends.begin(), ends.end(), folded(n)) != ends.end();
  };
  auto add = [](std::vector<std::string>& list, const std::string& s) {  // SDL ignores case
    const auto same = [&](const std::string& t) { return folded(t) == folded(s); };
    if (std::none_of(list.begin(), list.end(), same)) list.push_back(s);
  };
  for (const sdl::Channel& c : channels) {
    for (const sdl::Path& p : c.paths) {
      for (const std::string& s : p.signals) {
        if (folded(p.from) == "env" && is_end(p.to)) add(in, s);
        if (folded(p.to) == "env" && is_end(p.from)) add(out, s);
      }
    }
  }
}

std::optional<SignalInterface> signal_interface(const sdl::System& system,
                                                const std::vector<const sdl::Block*>& blocks,
                                                const std::string& name, const asn1::DataView& data,
                                                bipc::Diagnostics& diags) {
  const sdl::SignalDeclaration* declaration = nullptr;
  for (const sdl::SignalDeclaration& s : system.signals) {
    if (folded(s.name) == folded(name)) declaration = &s;
  }
  for (const sdl::Block* b : blocks) {
    for (const sdl::SignalDeclaration& s : b->signals) {
      if (folded(s.name) == folded(name)) declaration = &s;
    }
  }
  if (declaration == nullptr) {
    diags.error(system.at, "signal '" + name + "' is not declared in system " + system.name);
    return std::nullopt;
  }
  SignalInterface out;
  out.name = bip_identifier(declaration->name);
  out.kind = InterfaceKind::Sporadic;
  out.at = declaration->at;
  for (std::size_t k = 0; k < declaration->parameter_types.size(); ++k) {
    SignalParameter p;
    p.name = "p" + std::to_string(k + 1);
    p.asn1_type = declaration->parameter_types[k];
    p.at = declaration->at;
    auto leaves = leaves_of(data, p.asn1_type, declaration->at, diags);
    if (!leaves) return std::nullopt;
    p.leaves = std::move(*leaves);
    out.parameters.push_back(std::move(p));
  }
  return out;
}

}  // namespace

std::optional<FunctionSignature> sdl_system_signature(const sdl::System& system,
                                                      const std::string& process,
                                                      const asn1::DataView& data,
                                                      bipc::Diagnostics& diags) {
  std::vector<const sdl::Block*> path;
  if (!block_path(system.blocks, process, path)) {
    diags.error(system.at, "system " + system.name + " has no process '" + process + "'");
    return std::nullopt;
  }
  std::vector<std::string> ends = {folded(process)};
  for (const sdl::Block* b : path) ends.push_back(folded(b->name));
  std::vector<std::string> in, out;
  add_paths(system.channels, ends, in, out);
  for (const sdl::Block* b : path) add_paths(b->routes, ends, in, out);
  FunctionSignature signature;
  signature.name = bip_identifier(process);
  signature.language = "SDL";
  const std::size_t errors = diags.error_count();
  for (const std::string& s : in) {
    if (auto i = signal_interface(system, path, s, data, diags)) signature.provided.push_back(*i);
  }
  for (const std::string& s : out) {
    if (auto i = signal_interface(system, path, s, data, diags)) signature.required.push_back(*i);
  }
  if (diags.error_count() > errors) return std::nullopt;
  separate_data_names(signature);
  return signature;
}

}  // namespace smcbip::taste2bip
