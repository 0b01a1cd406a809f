// Reads `@stochastic(dist=..., clk=..., param=...)` on a port into the IR's distribution.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

namespace {

struct DistributionName {
  const char* name;
  ir::Distribution distribution;
  std::size_t params;  // how many `param` values it takes; custom: one file name
};

constexpr DistributionName kDistributions[] = {
    {"normal", ir::Distribution::Normal, 2},   {"exponential", ir::Distribution::Exponential, 1},
    {"gamma", ir::Distribution::Gamma, 2},     {"chi2", ir::Distribution::Chi2, 1},
    {"uniform", ir::Distribution::Uniform, 2}, {"lognormal", ir::Distribution::Lognormal, 2},
    {"weibull", ir::Distribution::Weibull, 2}, {"custom", ir::Distribution::Custom, 1},
};

const DistributionName* find_distribution(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const DistributionName& d : kDistributions) {
    if (name == d.name) return &d;
  }
  return nullptr;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// The empirical CDF file, relative to the folder of the package that names it.
std::string custom_file(const std::string& name, const ast::Package* package) {
  const std::filesystem::path file(trimmed(name));
  if (file.is_absolute() || package == nullptr || package->path.empty()) return file.string();
  return (std::filesystem::path(package->path).parent_path() / file).lexically_normal().string();
}

const std::optional<std::string>* param(const ast::Annotation& a, const char* key) {
  for (const ast::AnnotationParam& p : a.params) {
    if (p.key.text == key) return &p.value;
  }
  return nullptr;
}

}  // namespace

std::optional<ir::Stochastic> lower_stochastic(const ast::Annotation& annotation,
                                               const ast::AtomTypeDecl& atom,
                                               const ast::Package* package, Lowering& lowering) {
  auto fail = [&](const std::string& why) -> std::optional<ir::Stochastic> {
    lowering.diags().error(annotation.loc, "@stochastic: " + why);
    return std::nullopt;
  };
  const auto* dist = param(annotation, "dist");
  if (dist == nullptr || !dist->has_value()) return fail("missing dist=...");
  const DistributionName* d = find_distribution(**dist);
  if (d == nullptr) return fail("unknown distribution '" + **dist + "'");

  ir::Stochastic out;
  out.distribution = d->distribution;
  if (const auto* clk = param(annotation, "clk"); clk != nullptr && clk->has_value()) {
    const std::string name = trimmed(**clk);
    for (std::size_t i = 0; i < atom.clocks.size() && out.clock == ir::kNone; ++i) {
      if (atom.clocks[i].name.text == name) out.clock = static_cast<ir::Index>(i);
    }
    if (out.clock == ir::kNone) return fail("'" + name + "' is not a clock of the atom");
  }
  const auto* values = param(annotation, "param");
  if (values == nullptr || !values->has_value()) return fail("missing param=\"...\"");
  if (d->distribution == ir::Distribution::Custom) {
    out.custom_file = custom_file(**values, package);
    return out;
  }
  const std::vector<std::string> parts = split_commas(**values);
  if (parts.size() != d->params) {
    return fail(std::string(d->name) + " takes " + std::to_string(d->params) +
                " parameter(s), got " + std::to_string(parts.size()));
  }
  CodeCompiler code(lowering);
  for (const std::string& part : parts) {
    std::optional<ir::Code> compiled = code.stochastic_param(part, atom);
    if (!compiled) {
      return fail("parameter '" + trimmed(part) +
                  "' is neither a number nor a numeric parameter or data of the atom");
    }
    out.params.push_back(std::move(*compiled));
  }
  return out;
}

}  // namespace smcbip::bipc::lower
