// Translating the processes of real SDL designs (a folder of .pr and .asn files) with their
// system's signature, and checking each atom with bipc in a package of its own.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "taste2bip/translate/sdl_atom.h"
#include "tests/engines/temp_model.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip::test {

namespace fs = std::filesystem;

/// What became of one process: translated and accepted by bipc, or the first diagnostic.
struct ProcessResult {
  std::string file, process;
  bool ok = false;
  std::string message;
};

inline std::vector<fs::path> files_with(const fs::path& folder, const std::string& extension) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().extension() == extension) out.push_back(it->path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// A package holding `atom` alone, with the port types of `signature`, instantiated as Syst().
inline std::string single_atom_package(const FunctionSignature& signature, const AtomType& atom) {
  std::vector<std::pair<std::string, std::vector<std::string>>> port_types = {{"Port", {}}};
  collect_port_types(signature, port_types);
  std::string text = "package sdlreal\n";
  std::vector<std::string> externs = atom.extern_types;
  for (const auto& [name, types] : port_types) {
    for (const std::string& t : types) {
      const bool scalar = t == "int" || t == "bool" || t == "float" || t == "string";
      if (!scalar && std::find(externs.begin(), externs.end(), t) == externs.end()) {
        externs.push_back(t);
      }
    }
  }
  for (const std::string& t : externs) text += "  extern data type " + t + "\n";
  for (const std::string& f : atom.extern_functions) text += "  " + f + "\n";
  for (const auto& [name, types] : port_types) {
    text += "  port type " + name + "(";
    for (std::size_t k = 0; k < types.size(); ++k) {
      text += (k ? ", " : "") + types[k] + " v" + std::to_string(k);
    }
    text += ")\n";
  }
  return text + atom.text + "  compound type Syst()\n    component " + atom.name +
         " f()\n  end\nend\n";
}

/// Empty when bipc accepts `atom` in a package of its own, else bipc's first diagnostic.
inline std::string check_atom(const FunctionSignature& signature, const AtomType& atom) {
  const tests::TempDir dir;
  const fs::path file = dir.write("model.bip", single_atom_package(signature, atom));
  bipc::FrontendResult checked = bipc::run_frontend({file.string(), {}, "Syst()"}, true);
  if (checked.system) return {};
  const std::string text = checked.diags.format(checked.model.files);
  return "bipc: " + text.substr(0, text.find('\n'));
}

/// `name` with case and '-'/'_' ignored, as SDL matches names.
inline std::string detail_folded(const std::string& name) {
  std::string out;
  for (char c : name) {
    out += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

/// The first line of `text`.
inline std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

inline void processes_in(const std::vector<sdl::Block>& blocks,
                         std::vector<const sdl::Process*>& out,
                         std::vector<const sdl::Procedure*>& procedures) {
  for (const sdl::Block& b : blocks) {
    for (const sdl::Process& p : b.processes) {
      if (!p.is_referenced) out.push_back(&p);
    }
    for (const sdl::Procedure& p : b.procedures) procedures.push_back(&p);
    processes_in(b.blocks, out, procedures);
  }
}

inline bool declares(const std::vector<sdl::Block>& blocks, const std::string& process) {
  for (const sdl::Block& b : blocks) {
    for (const sdl::Process& p : b.processes) {
      if (p.name == process) return true;
    }
    if (declares(b.blocks, process)) return true;
  }
  return false;
}

/// Translates every process of the .pr files of `folder`, with the data view of `asn_files`,
/// and checks each atom with bipc.
inline std::vector<ProcessResult> translate_folder(const fs::path& folder,
                                                   const std::vector<fs::path>& asn_files) {
  bipc::SourceFiles files;
  bipc::Diagnostics read_diags;
  asn1::DataView view;
  for (const fs::path& a : asn_files) {
    asn1::read_asn1(file_text(a), files.add(a.filename().string()), view, read_diags);
  }
  asn1::resolve(view, read_diags);
  std::vector<sdl::SdlFile> sdl;
  std::vector<std::string> names;
  for (const fs::path& p : files_with(folder, ".pr")) {
    sdl.push_back(sdl::read_sdl(file_text(p), files.add(p.filename().string()), read_diags));
    names.push_back(p.filename().string());
  }
  std::vector<const sdl::Procedure*> procedures;
  std::vector<const sdl::System*> systems;
  for (const sdl::SdlFile& f : sdl) {
    for (const sdl::Procedure& p : f.procedures) procedures.push_back(&p);
    for (const sdl::System& s : f.systems) {
      systems.push_back(&s);
      for (const sdl::Procedure& p : s.procedures) procedures.push_back(&p);
    }
  }
  std::vector<ProcessResult> results;
  for (std::size_t i = 0; i < sdl.size(); ++i) {
    std::vector<const sdl::Process*> processes;
    for (const sdl::Process& p : sdl[i].processes) {
      if (!p.is_referenced) processes.push_back(&p);
    }
    for (const sdl::System& s : sdl[i].systems) processes_in(s.blocks, processes, procedures);
    for (const sdl::Process* p : processes) {
      ProcessResult r{names[i], p->name, false, {}};
      bipc::Diagnostics diags;
      const sdl::System* system = nullptr;
      for (const sdl::System* s : systems) system = declares(s->blocks, p->name) ? s : system;
      std::optional<FunctionSignature> signature;
      if (system == nullptr) {
        r.message = "no system declares the process";
      } else {
        signature = sdl_system_signature(*system, p->name, view, diags);
      }
      std::optional<AtomType> atom;
      if (signature) atom = sdl_atom(*signature, *p, procedures, view, diags);
      if (atom) {
        r.message = check_atom(*signature, *atom);
        r.ok = r.message.empty();
      } else if (r.message.empty()) {
        r.message = first_line(diags.format(files));
      }
      results.push_back(std::move(r));
    }
  }
  return results;
}

}  // namespace smcbip::taste2bip::test
