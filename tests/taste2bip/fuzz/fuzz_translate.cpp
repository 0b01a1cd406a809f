// The SDL translation driven from memory: every process of a text translated to an atom, and
// every atom that the translation gives put in a package that bipc must accept.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "fuzz_taste.h"
#include "taste2bip/asn1/taste_basic_types.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "taste2bip/translate/package.h"
#include "taste2bip/translate/sdl_atom.h"

namespace smcbip::taste2bip::fuzz {

namespace {

/// The types the seeds' processes declare their variables and signals with.
const char* const kTypes = R"(Fuzz-Types DEFINITIONS AUTOMATIC TAGS ::= BEGIN
  MyInteger ::= INTEGER (0 .. 255)
  MyReal ::= REAL (-1000.0 .. 1000.0)
  MyBool ::= BOOLEAN
  MyEnum ::= ENUMERATED { one, two, three }
  MySeq ::= SEQUENCE { a MyInteger, b MyBool, c MyEnum }
  MyChoice ::= CHOICE { a MyInteger, b MyBool }
  MySeqOf ::= SEQUENCE (SIZE (0 .. 3)) OF MyInteger
  MyOctets ::= OCTET STRING (SIZE (0 .. 8))
END
)";

const asn1::DataView& data_view() {
  static const asn1::DataView view = [] {
    asn1::DataView v;
    bipc::Diagnostics diags;
    asn1::read_asn1(kTypes, 1, v, diags);
    asn1::read_asn1(std::string(asn1::taste_basic_types_text()), 2, v, diags);
    asn1::resolve(v, diags);
    if (diags.has_errors()) std::abort();
    return v;
  }();
  return view;
}

[[noreturn]] void fail(const std::string& why) {
  std::cerr << "taste2bip fuzz (sdlatom): " << why << "\n";
  std::abort();
}

/// The atom in a package with what it needs, instantiated alone as Syst().
std::string package_of(const FunctionSignature& f, const AtomType& atom) {
  std::string text = "package fuzz\n";
  for (const std::string& t : atom.extern_types) text += "  extern data type " + t + "\n";
  for (const std::string& e : atom.extern_functions) text += "  " + e + "\n";
  std::vector<std::pair<std::string, std::vector<std::string>>> ports{{"Port", {}}};
  collect_port_types(f, ports);
  for (const auto& [name, types] : ports) {
    std::string parameters;
    for (std::size_t i = 0; i < types.size(); ++i) {
      parameters += (i ? ", " : "") + types[i] + " a" + std::to_string(i);
    }
    text += "  port type " + name + "(" + parameters + ")\n";
  }
  text += atom.text;
  text += "  compound type Syst()\n    component " + atom.name + " " + atom.name + "()\n  end\n";
  return text + "end\n";
}

void translate_process(const sdl::Process& process, const FunctionSignature& signature,
                       const std::vector<const sdl::Procedure*>& procedures) {
  bipc::Diagnostics diags;
  const auto atom = sdl_atom(signature, process, procedures, data_view(), diags);
  if (std::getenv("TASTE2BIP_FUZZ_VERBOSE") != nullptr) {
    std::cerr << process.name << ": " << (atom ? "translated" : "refused") << "\n"
              << diags.format(bipc::SourceFiles{{"input.pr"}});
  }
  if (!atom) {
    if (!diags.has_errors()) fail("a translation failed without an error");
    return;
  }
  const std::string problems = bipc_diagnostics(package_of(signature, *atom), "fuzz");
  if (!problems.empty()) fail("bipc refuses the translation:\n" + problems + atom->text);
}

}  // namespace

void translate_sdl_on(const std::string& text) {
  bipc::Diagnostics diags;
  const sdl::SdlFile file = sdl::read_sdl(text, 0, diags);
  if (std::getenv("TASTE2BIP_FUZZ_VERBOSE") != nullptr) {
    std::cerr << diags.format(bipc::SourceFiles{{"input.pr"}});
  }
  std::vector<const sdl::Procedure*> procedures;
  for (const sdl::Procedure& p : file.procedures) procedures.push_back(&p);
  for (const sdl::System& system : file.systems) {
    for (const sdl::Procedure& p : system.procedures) procedures.push_back(&p);
  }
  for (const sdl::System& system : file.systems) {
    for (const sdl::Block& block : system.blocks) {
      for (const sdl::Process& process : block.processes) {
        if (process.is_referenced) continue;
        bipc::Diagnostics signature_diags;
        const auto signature =
            sdl_system_signature(system, process.name, data_view(), signature_diags);
        if (signature) translate_process(process, *signature, procedures);
      }
    }
  }
  for (const sdl::Process& process : file.processes) {
    FunctionSignature alone;
    alone.name = "P";
    alone.language = "SDL";
    translate_process(process, alone, procedures);
  }
}

}  // namespace smcbip::taste2bip::fuzz
