#include "smc/tools/model_loading.h"

#include <iostream>

#include "bipc/input_file.h"

namespace smcbip::tools {

std::optional<bipc::ir::System> load_model_system(const bipc::FrontendOptions& frontend,
                                                  LoadFailure& failure) {
  bipc::require_model_file(frontend.file);
  bipc::FrontendResult model = bipc::run_frontend(frontend, /*need_system=*/true);
  bipc::Diagnostics sorted = model.diags;
  sorted.sort_by_location();
  std::cerr << sorted.format(model.model.files);
  failure = LoadFailure::Errors;
  if (model.diags.has_errors()) return std::nullopt;
  if (!model.system) {
    std::cerr << "smcbip: error: no root given and " << frontend.file
              << " has no single top compound; use --root\n";
    failure = LoadFailure::NoRoot;
    return std::nullopt;
  }
  return std::move(model.system);
}

monitors::ParsedProperties load_property_file(const std::string& path,
                                              const std::vector<std::string>& parameters) {
  return monitors::parse_properties(bipc::read_input_file(path, "the property file"), path,
                                    parameters);
}

}  // namespace smcbip::tools
