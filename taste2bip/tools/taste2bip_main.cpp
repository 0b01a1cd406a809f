// taste2bip: a TASTE design (interface view, ASN.1 data view, SDL) as BIP packages.
//
// Exit codes: 0 success, 2 input or usage error, 3 internal error.
#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "bipc/exit_codes.h"
#include "bipc/options.h"
#include "bipc/output_file.h"
#include "bipc/tool_main.h"
#include "taste2bip/names.h"
#include "taste2bip/translate/read_design.h"

namespace {

using namespace smcbip;
using namespace smcbip::taste2bip;

struct Arguments {
  DesignFiles design;
  std::vector<std::string> atoms;  // FUNCTION=FILE
  std::string output;
  PackageOptions package;
};

void parse_atoms(const std::vector<std::string>& atoms, DesignFiles& design) {
  for (const std::string& a : atoms) {
    const auto equal = a.find('=');
    if (equal == std::string::npos || equal == 0 || equal + 1 == a.size()) {
      throw UsageError("--atom takes FUNCTION=FILE, not '" + a + "'");
    }
    design.behaviours[a.substr(0, equal)] = a.substr(equal + 1);
  }
}

int translate_design(const Arguments& args) {
  bipc::SourceFiles files;
  bipc::Diagnostics diags;
  std::vector<std::string> notes;
  std::optional<Packages> packages;
  if (auto design = read_design(args.design, files, diags, notes)) {
    packages = translate(*design, args.package, diags);
  }
  diags.sort_by_location();
  std::cerr << diags.format(files);
  if (!packages) return exit_codes::kInputError;
  if (const std::string problems = bipc_diagnostics(packages->nominal, args.package.name);
      !problems.empty()) {
    throw std::runtime_error("the BIP written for this design does not pass bipc's check:\n" +
                             problems);
  }

  std::string report;
  for (const std::string& note : notes) report += note + "\n";
  report += packages->report;
  const std::string& name = args.package.name;
  std::vector<bipc::NamedText> written{{name + ".bip", packages->nominal},
                                       {name + "_faulty.bip", packages->faulty},
                                       {name + "_requirements.bip", packages->requirements},
                                       {name + "_report.txt", report}};
  for (const OutputFile& file : packages->files) written.push_back({file.name, file.text});
  std::string error;
  if (!bipc::write_files_atomically(args.output, written, error)) throw InputError(error);
  std::cout << report << "wrote " << args.output << "/" << name << ".bip (root Syst()), " << name
            << "_faulty.bip, " << name << "_requirements.bip, " << name << "_report.txt";
  if (!packages->files.empty()) {
    std::cout << " and the " << packages->files.size()
              << " files of the C/C++ bodies: the model runs compiled (bipc gen " << args.output
              << "/" << name << ".bip --root 'Syst()' -o DIR, then smcbip simulate|check "
              << "--compiled DIR)";
  }
  std::cout << "\n";
  return exit_codes::kSuccess;
}

int run(int argc, char** argv) {
  CLI::App app{"taste2bip: a TASTE design (interface view, data view, SDL) as BIP packages"};
  Arguments args;
  app.add_option("IV", args.design.interface_view,
                 "the interface view: InterfaceView.aadl or interfaceview.xml")
      ->required()
      ->type_name("FILE");
  cli::once_per_use(app.add_option("--dataview", args.design.data_views,
                                   "an ASN.1 file of the data view (default: every .asn file "
                                   "in the interface view's folder and below)"))
      ->type_name("FILE");
  cli::once_per_use(app.add_option("--sdl", args.design.sdl_folders,
                                   "a folder holding <function>.pr files (default: the "
                                   "interface view's folder)"))
      ->type_name("DIR");
  cli::once_per_use(app.add_option("--src", args.design.source_folders,
                                   "a folder holding the bodies of C and C++ functions, "
                                   "<function>.c, .cc or .cpp (default: the interface view's "
                                   "folder)"))
      ->type_name("DIR");
  cli::once_per_use(app.add_option("--atom", args.atoms,
                                   "the atom type (BIP) of a function without SDL, instead of "
                                   "an abstract one"))
      ->type_name("FUNCTION=FILE");
  app.add_option("-o,--output", args.output, "the folder to write the packages in")
      ->required()
      ->type_name("DIR");
  app.add_option("--package", args.package.name, "the nominal package's name")
      ->capture_default_str()
      ->type_name("NAME");
  const std::map<std::string, Wcet> wcet{
      {"zero", Wcet::Zero}, {"interval", Wcet::Interval}, {"uniform", Wcet::Uniform}};
  app.add_option("--wcet", args.package.wcet,
                 "how long a provided interface runs: no time, any time in its WCET bounds, or a "
                 "uniform draw in them (default zero)")
      ->transform(cli::named_choice(wcet))
      ->option_text(cli::choices_text({"zero", "interval", "uniform"}));
  cli::add_version_flags(app, "taste2bip");
  if (const int code = cli::parse_command_line(app, argc, argv); code >= 0) return code;
  if (bip_identifier(args.package.name) != args.package.name) {
    throw UsageError("--package '" + args.package.name + "' is not a BIP identifier");
  }
  parse_atoms(args.atoms, args.design);
  return translate_design(args);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::guarded_main("taste2bip", exit_codes::kJudgingCodes, [&] { return run(argc, argv); });
}
