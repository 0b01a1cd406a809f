#include "smc/tools/model_loading.h"

#include <iostream>

#include "bipc/bipc.h"

namespace smcbip::tools {

std::optional<bipc::ir::System> load_model_system(const std::string& file, const std::string& root,
                                                  const std::vector<std::string>& include_dirs) {
  bipc::FrontendOptions frontend;
  frontend.file = file;
  frontend.root = root;
  frontend.include_dirs = include_dirs;
  bipc::FrontendResult model = bipc::run_frontend(frontend, /*need_system=*/true);
  if (!model.diags.has_errors() && model.system) return std::move(model.system);
  bipc::Diagnostics sorted = model.diags;
  sorted.sort_by_location();
  std::cerr << sorted.format(model.model.files);
  if (!model.diags.has_errors()) {
    std::cerr << "smcbip: error: " << file
              << " has no single top compound; name the root with --root\n";
  }
  return std::nullopt;
}

}  // namespace smcbip::tools
