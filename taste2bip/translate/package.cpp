#include "taste2bip/translate/package.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "taste2bip/translate/abstract_atom.h"
#include "taste2bip/translate/c_body.h"
#include "taste2bip/translate/detail/faulty_package.h"
#include "taste2bip/translate/detail/package_parts.h"
#include "taste2bip/translate/sdl_atom.h"

namespace smcbip::taste2bip {

namespace {

using detail::PackageParts;

bool same_name(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

struct FoundProcess {
  const sdl::Process* process = nullptr;
  std::vector<const sdl::Procedure*> procedures;  // visible from outside the process
};

void search_block(const sdl::Block& block, const std::string& name, FoundProcess& found) {
  for (const sdl::Process& p : block.processes) {
    if (!p.is_referenced && same_name(p.name, name)) found.process = &p;
  }
  for (const sdl::Procedure& p : block.procedures) found.procedures.push_back(&p);
  for (const sdl::Block& inner : block.blocks) search_block(inner, name, found);
}

/// The process named like `function` (SDL names ignore case) in the files, with the procedures
/// declared beside it.
FoundProcess find_process(const std::vector<sdl::SdlFile>& files, const std::string& function) {
  for (const sdl::SdlFile& file : files) {
    FoundProcess found;
    for (const sdl::Process& p : file.processes) {
      if (!p.is_referenced && same_name(p.name, function)) found.process = &p;
    }
    for (const sdl::System& system : file.systems) {
      for (const sdl::Procedure& p : system.procedures) found.procedures.push_back(&p);
      for (const sdl::Block& block : system.blocks) search_block(block, function, found);
    }
    for (const sdl::Procedure& p : file.procedures) found.procedures.push_back(&p);
    if (found.process != nullptr) return found;
  }
  return {};
}

const std::string* user_behaviour(const Design& design, const FunctionSignature& f) {
  for (const auto& [name, text] : design.behaviours) {
    if (same_name(name, f.source->name) || name == f.name) return &text;
  }
  return nullptr;
}

/// The body the function's atom calls: none when the user gave its atom type.
const FunctionBody* function_body(const Design& design, const FunctionSignature& f) {
  const auto it = design.bodies.find(f.source->name);
  if (it == design.bodies.end() || user_behaviour(design, f) != nullptr) return nullptr;
  return &it->second;
}

/// The atoms of a function: the nominal one, and for an SDL function the faulty package's (its
/// fault signals as fault transitions; the other functions' faulty atoms repeat the nominal
/// one's declarations).
struct FunctionAtoms {
  std::optional<AtomType> nominal, faulty;
};

FunctionAtoms function_atoms(const Design& design, const FunctionSignature& f,
                             bipc::Diagnostics& diags) {
  FunctionAtoms out;
  if (const std::string* text = user_behaviour(design, f)) {
    AtomType given;
    given.name = f.name;
    given.text = *text;
    given.notes.push_back(f.name + ": the atom type given for it");
    out.nominal = std::move(given);
    return out;
  }
  if (function_body(design, f) != nullptr) {
    out.nominal = c_body_atom(f, design.data, diags);
    return out;
  }
  if (!same_name(f.language, "SDL")) {
    out.nominal = abstract_atom(f);
    return out;
  }
  const FoundProcess found = find_process(design.sdl, f.source->name);
  if (found.process == nullptr) {
    diags.error(f.source->at, "SDL function " + f.source->name +
                                  ": no process of that name in the SDL read (taste2bip reads " +
                                  f.source->name +
                                  ".pr, any case, under --sdl or the view's folder)");
    return out;
  }
  out.nominal = sdl_atom(f, *found.process, found.procedures, design.data, diags);
  if (out.nominal) {
    out.faulty = sdl_fault_atom(f, *found.process, found.procedures, design.data, diags);
  }
  return out;
}

bool distinct_instances(const std::vector<FunctionSignature>& functions, bipc::Diagnostics& diags) {
  std::set<std::string> names;
  bool ok = true;
  for (const FunctionSignature& f : functions) {
    std::vector<std::string> own{f.name};
    for (const SignalInterface& p : f.provided) own.push_back(f.name + "_" + p.name);
    for (const std::string& n : own) {
      if (!names.insert(n).second) {
        diags.error(f.source->at, "function " + f.source->name + " gives the BIP name " + n +
                                      ", which another function or interface already has");
        ok = false;
      }
    }
  }
  return ok;
}

std::string nominal_text(const PackageOptions& options, const PackageParts& parts,
                         const std::string& annotation) {
  std::string text =
      "// The TASTE design as BIP, written by taste2bip: an atom per function, a\n"
      "// timing wrapper per provided interface, a connector per call.\n";
  text += annotation + "package " + options.name + "\n";
  text += parts.extern_types.text() + parts.port_types.text() + parts.connector_types.text();
  text += parts.atom_types.text();
  text += "  compound type Syst()\n";
  for (const std::string& c : parts.function_components) text += c;
  for (const std::string& c : parts.components) text += c;
  for (const std::string& c : parts.connectors) text += c;
  return text + "  end\nend\n";
}

std::string position(const Design& design, const bipc::Location& at) {
  const bool named = design.files != nullptr && at.file < design.files->paths.size();
  return bipc::position_text(named ? design.files->path(at.file) : "", at.line, at.column);
}

void collect_extern_types(const FunctionSignature& f, PackageParts& parts) {
  for (const auto* list : {&f.provided, &f.required}) {
    for (const SignalInterface& i : *list) {
      for (const SignalParameter& p : i.parameters) {
        for (const std::string& t : extern_types_in(p.leaves)) {
          parts.extern_types.add(t, "  extern data type " + t + "\n");
        }
      }
    }
  }
}

std::string report_text(const Design& design, const InterfaceView& view,
                        const PackageParts& parts) {
  std::string text;
  for (const Assumption& a : view.assumptions) {
    text += position(design, a.at) + ": assumed: " + a.text + "\n";
  }
  for (const std::string& line : parts.report) text += line + "\n";
  return text;
}

}  // namespace

std::optional<Packages> translate(const Design& design, const PackageOptions& options,
                                  bipc::Diagnostics& diags) {
  const std::size_t errors = diags.error_count();
  const InterfaceView view = flatten(design.view, diags);
  std::vector<FunctionSignature> functions;
  for (std::size_t i = 0; i < view.functions.size(); ++i) {
    functions.push_back(function_signature(view, i, design.data, diags));
  }
  if (diags.error_count() > errors || !distinct_instances(functions, diags)) return std::nullopt;

  PackageParts parts;
  std::vector<AtomType> atoms, faulty;
  for (const FunctionSignature& f : functions) {
    FunctionAtoms made = function_atoms(design, f, diags);
    std::optional<AtomType>& atom = made.nominal;
    if (!atom) continue;
    if (made.faulty) faulty.push_back(std::move(*made.faulty));
    for (const std::string& t : atom->extern_types) {
      parts.extern_types.add(t, "  extern data type " + t + "\n");
    }
    for (const std::string& e : atom->extern_functions) parts.extern_types.add(e, "  " + e + "\n");
    parts.report.push_back(f.source->name + " (" + f.language + "): atom type " + atom->name);
    for (const std::string& note : atom->notes) parts.report.push_back("  " + note);
    atoms.push_back(std::move(*atom));
  }
  for (const FunctionSignature& f : functions) {
    collect_extern_types(f, parts);
    std::vector<std::pair<std::string, std::vector<std::string>>> port_types;
    collect_port_types(f, port_types);
    for (const auto& [name, types] : port_types) detail::use_port_type(types, parts);
  }
  for (std::size_t i = 0; i < functions.size(); ++i) {
    detail::connect_function(view, functions, i, options.wcet, parts, diags);
  }
  if (diags.error_count() > errors) return std::nullopt;

  for (const AtomType& atom : atoms) {
    parts.atom_types.add(atom.name, atom.text);
    parts.function_components.push_back("    component " + atom.name + " " + atom.name + "()\n");
  }
  std::vector<std::pair<const FunctionSignature*, const FunctionBody*>> with_bodies;
  for (const FunctionSignature& f : functions) {
    if (const FunctionBody* body = function_body(design, f)) with_bodies.emplace_back(&f, body);
  }
  BodyFiles bodies = c_body_files(options.name, with_bodies, design.data);
  Packages out;
  out.nominal = nominal_text(options, parts, bodies.annotation);
  out.files = std::move(bodies.files);
  out.faulty = detail::faulty_package(
      options.name, parts.extern_types.text() + parts.port_types.text(), atoms, faulty);
  out.requirements = detail::requirements_package(options.name);
  out.report = report_text(design, view, parts);
  return out;
}

}  // namespace smcbip::taste2bip
