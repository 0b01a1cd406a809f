#include "bipc/bipc.h"
#include "taste2bip/translate/package.h"

namespace smcbip::taste2bip {

std::string bipc_diagnostics(const std::string& text, const std::string& name) {
  bipc::LoadedModel model;
  bipc::Diagnostics diags;
  const std::uint32_t file = model.files.add(name + ".bip");
  model.packages.push_back(bipc::parse_package(text, file, diags));
  model.main = model.packages.back().get();
  bool ok = !diags.has_errors() && model.main != nullptr && bipc::check(model, diags);
  if (ok) {
    auto root = bipc::parse_root("Syst()", model.files.add("<root>"), diags);
    ok = root && bipc::check_root(model, *root, diags) && bipc::instantiate(model, *root, diags);
  }
  return ok ? std::string() : diags.format(model.files);
}

}  // namespace smcbip::taste2bip
