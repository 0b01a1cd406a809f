// The front end driven from memory, for the fuzzer and its regression replay.
#include "fuzz_frontend.h"

#include <string>

#include "bipc/bipc.h"

namespace smcbip::bipc::fuzz {

void run_frontend_on(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  LoadedModel model;
  Diagnostics diags;
  const std::uint32_t file = model.files.add("fuzz.bip");
  std::unique_ptr<ast::Package> package = parse_package(text, file, diags);
  if (!package || diags.has_errors()) return;
  // `use` clauses cannot be satisfied from memory; such inputs stop at the parser.
  if (!package->uses.empty()) return;
  model.main = package.get();
  model.packages.push_back(std::move(package));
  if (!check(model, diags)) return;
  std::optional<std::string> root_text = default_root(model);
  if (!root_text) return;
  std::optional<ast::ComponentDecl> root = parse_root(*root_text, file, diags);
  if (!root || !check_root(model, *root, diags)) return;
  (void)instantiate(model, *root, diags);
}

}  // namespace smcbip::bipc::fuzz
