// Translating the SDL functions of real TASTE designs: the signature of each comes from the
// design's interface view (AADL or XML, flattened), its data from the design's ASN.1 files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "taste2bip/interface_view/interface_view.h"
#include "tests/taste2bip/sdl_atom_real_support.h"

namespace smcbip::taste2bip::test {

inline std::vector<fs::path> files_below(const fs::path& folder, const std::string& extension) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().extension() == extension) out.push_back(it->path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The process of each .pr file below `design` matched by name with an SDL function of the
/// design's interface view, translated and checked with bipc.
inline std::vector<ProcessResult> translate_design(const fs::path& design) {
  bipc::SourceFiles files;
  bipc::Diagnostics diags;
  asn1::DataView data;
  for (const fs::path& a : files_with(design, ".asn")) {
    asn1::read_asn1(file_text(a), files.add(a.filename().string()), data, diags);
  }
  if (fs::exists(design.parent_path() / "taste-types.asn") &&
      !fs::exists(design / "taste-types.asn")) {
    const fs::path a = design.parent_path() / "taste-types.asn";
    asn1::read_asn1(file_text(a), files.add(a.filename().string()), data, diags);
  }
  asn1::resolve(data, diags);
  InterfaceView read;
  if (fs::exists(design / "interfaceview.xml")) {
    read = read_xml_interface_view(file_text(design / "interfaceview.xml"),
                                   files.add("interfaceview.xml"), diags);
  } else {
    read = read_aadl_interface_view(file_text(design / "InterfaceView.aadl"),
                                    files.add("InterfaceView.aadl"), diags);
  }
  const InterfaceView view = flatten(read, diags);
  std::vector<ProcessResult> results;
  for (const fs::path& pr : files_below(design, ".pr")) {
    bipc::Diagnostics local;
    const sdl::SdlFile file =
        sdl::read_sdl(file_text(pr), files.add(pr.filename().string()), local);
    std::vector<const sdl::Procedure*> procedures;
    for (const sdl::Procedure& p : file.procedures) procedures.push_back(&p);
    for (const sdl::Process& p : file.processes) {
      if (p.is_referenced) continue;
      ProcessResult r{pr.filename().string(), p.name, false, "no function of that name"};
      for (std::size_t i = 0; i < view.functions.size(); ++i) {
        if (detail_folded(view.functions[i].name) != detail_folded(p.name)) continue;
        const FunctionSignature signature = function_signature(view, i, data, local);
        std::optional<AtomType> atom = sdl_atom(signature, p, procedures, data, local);
        r.message = atom ? check_atom(signature, *atom) : first_line(local.format(files));
        r.ok = r.message.empty();
      }
      results.push_back(std::move(r));
    }
  }
  return results;
}

}  // namespace smcbip::taste2bip::test
