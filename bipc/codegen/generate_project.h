// The standalone CMake project that `bipc gen` writes: the model's compiled code, its IR and
// identity embedded, its extern C++ bound, a main program and a plugin for `smcbip --compiled`.
#pragma once

#include <string>
#include <vector>

#include "bipc/codegen/generate_cpp.h"
#include "bipc/ir/ir.h"
#include "bipc/ir/model_hash.h"

namespace smcbip::bipc::codegen {

struct ProjectOptions {
  GenerateOptions code;
  /// Write main.cpp and its executable (the options of `smcbip simulate`); without it the
  /// project is a library for a host program, and the plugin.
  bool main = true;
  std::string model_file;  // as given to bipc gen, for the comments
  std::string root;        // the root instantiation, e.g. `System()`
  /// The model's extern C++ files (ir::extern_sources_of): copied under extern/ and hashed.
  ir::ExternSources extern_sources;
  /// The version of smcbip the project needs (`find_package(smcbip VERSION)`).
  std::string smcbip_version;
};

/// Two extern files that would land on the same path under extern/.
struct ExternSourceClash {
  std::string message;
};

/// The project's name: the namespace with `::` as `_` (its library, executable `<name>_simulate`
/// and plugin `<name>_plugin` are named after it).
std::string project_name(const std::string& name_space);

/// Every file of the project, relative to its folder:
///  - CMakeLists.txt: find_package(smcbip), the static library `<name>` (generated code, IR,
///    externs, extern sources), the executable `<name>_simulate` (with main), and the MODULE
///    `<name>_plugin` that smcbip loads with --compiled;
///  - model_code.{h,cpp} (generate_cpp), model.h (the API: kModelHash, system(), model(),
///    externs(), and Component, the model embedded in a host program), model_data.cpp (the IR as
///    CBOR bytes), model_externs.cpp (extern functions bound to the model's C++), plugin.cpp,
///    main.cpp (with `main`);
///  - extern/<name> for each extern source (a source by its file name, a header as written).
/// The hash is ir::model_hash(system, options.extern_sources). Throws ExternSourceClash when
/// two extern files would share a name, UntranslatableCode like generate_cpp.
std::vector<GeneratedFile> generate_project(const ir::System& system,
                                            const ProjectOptions& options);

}  // namespace smcbip::bipc::codegen
