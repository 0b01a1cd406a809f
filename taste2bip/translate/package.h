// A whole TASTE design as BIP packages: the nominal one (root `Syst()`: an atom per function, a
// timing wrapper per cyclic or sporadic provided interface, connectors for the calls), the
// faulty one and the requirements one of the FDIR workflow, and the report of what was
// translated and what was not.
//
// Names in the nominal package: the atom of function F is the instance `F` (type `F`); the
// wrapper of its provided interface p the instance `F_p`; the connectors are `F_p_start`,
// `F_p_done` (wrapper and function), `C_r_to_F_p` (caller C's required r to p).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/interface_view/interface_view.h"
#include "taste2bip/sdl/sdl_ast.h"
#include "taste2bip/writer/wrappers.h"

namespace smcbip::taste2bip {

/// A function's C or C++ body as found beside the design (c_body.h).
struct FunctionBody {
  std::string path;  // where it was read
  std::string text;
};

/// A file written beside the packages.
struct OutputFile {
  std::string name;  // relative to the output folder
  std::string text;
};

struct Design {
  InterfaceView view;   // as read: nested functions are flattened by translate
  asn1::DataView data;  // resolved
  std::vector<sdl::SdlFile> sdl;
  /// Atom types written by the user for functions without SDL (function name -> the text of an
  /// `atom type F() ... end` with the ports of signature.h), used instead of an abstract atom.
  std::map<std::string, std::string> behaviours;
  /// The bodies of C and C++ functions (function name as in the view -> its body): their atoms
  /// call them (c_body.h); a C or C++ function without one gets an abstract atom.
  std::map<std::string, FunctionBody> bodies;
  /// The files the locations above index, to name them in the report (null: line:col only).
  const bipc::SourceFiles* files = nullptr;
};

struct PackageOptions {
  std::string name = "taste";  // the nominal package; `<name>_faulty`, `<name>_requirements`
  Wcet wcet = Wcet::Zero;
};

struct Packages {
  std::string nominal, faulty, requirements;
  std::string report;  // lines: what became what, what was assumed, what was left out
  /// What the nominal package's `@cpp` names, to write beside it: the bodies and their shim.
  std::vector<OutputFile> files;
};

/// Translates `design`. Constructs it does not translate are located errors in `diags`
/// (nullopt then).
std::optional<Packages> translate(const Design& design, const PackageOptions& options,
                                  bipc::Diagnostics& diags);

/// What bipc's front end says of the nominal package `text` (package `name`) with root `Syst()`:
/// empty when it checks and instantiates, else its diagnostics. The translation's output must
/// pass: anything else is a fault of the translation.
std::string bipc_diagnostics(const std::string& text, const std::string& name);

}  // namespace smcbip::taste2bip
