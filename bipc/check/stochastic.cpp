// The `@stochastic(dist=..., clk=..., param="...")` annotation of atom ports (the stochastic
// real-time extension, see BIP.md): known distribution, clock of the atom, right parameters.
#include <array>
#include <cctype>
#include <regex>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

struct Distribution {
  const char* name;
  std::size_t params;
};

// `custom` takes the name of a file holding an empirical distribution function.
constexpr std::array<Distribution, 8> kDistributions = {{{"normal", 2},
                                                         {"exponential", 1},
                                                         {"gamma", 2},
                                                         {"chi2", 1},
                                                         {"uniform", 2},
                                                         {"lognormal", 2},
                                                         {"weibull", 2},
                                                         {"custom", 1}}};

const Distribution* find_distribution(const std::string& name) {
  for (const Distribution& d : kDistributions) {
    if (name == d.name) return &d;
  }
  return nullptr;
}

std::string trim(const std::string& text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])) != 0) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])) != 0) --end;
  return text.substr(begin, end - begin);
}

std::vector<std::string> split_params(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.push_back(trim(text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

bool is_number(const std::string& text) {
  static const std::regex kNumber(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  return std::regex_match(text, kNumber);
}

/// A distribution parameter: a number, or an atom parameter or data of numeric type.
void check_value(const std::string& item, const ast::AnnotationParam& param,
                 const ast::AtomTypeDecl& atom, Diagnostics& diags) {
  if (is_number(item)) return;
  const ast::TypeRef* type = nullptr;
  if (int d = index_of(atom.data, item); d >= 0) type = &atom.data[d].type;
  if (int p = index_of(atom.params, item); type == nullptr && p >= 0) type = &atom.params[p].type;
  if (type == nullptr) {
    diags.error(param.value_loc, "@stochastic parameter '" + item +
                                     "' must be a number or the name of a parameter or data of "
                                     "atom '" +
                                     atom.name.text + "'");
    return;
  }
  const ast::ValueType::Kind kind = type->resolved.kind;
  if (kind != ast::ValueType::Kind::Int && kind != ast::ValueType::Kind::Float &&
      kind != ast::ValueType::Kind::Error) {
    diags.error(param.value_loc, "@stochastic parameter '" + item + "' has type " +
                                     type_name(type->resolved) + ": expected int or float");
  }
}

void check_params(const ast::AnnotationParam& param, const Distribution& dist,
                  const ast::AtomTypeDecl& atom, Diagnostics& diags) {
  const std::vector<std::string> items = split_params(param.value.value_or(""));
  if (items.size() != dist.params || (items.size() == 1 && items.front().empty())) {
    diags.error(param.value_loc, "distribution '" + std::string(dist.name) + "' takes " +
                                     std::to_string(dist.params) + " parameter" +
                                     (dist.params == 1 ? "" : "s") + " in 'param', got \"" +
                                     param.value.value_or("") + "\"");
    return;
  }
  if (std::string(dist.name) == "custom") return;  // a file name, read when the model runs
  for (const std::string& item : items) check_value(item, param, atom, diags);
}

struct Keys {
  const ast::AnnotationParam* dist = nullptr;
  const ast::AnnotationParam* clk = nullptr;
  const ast::AnnotationParam* param = nullptr;
};

Keys collect_keys(const ast::Annotation& annotation, Diagnostics& diags) {
  Keys keys;
  for (const ast::AnnotationParam& param : annotation.params) {
    const std::string& key = param.key.text;
    const ast::AnnotationParam** slot = key == "dist"    ? &keys.dist
                                        : key == "clk"   ? &keys.clk
                                        : key == "param" ? &keys.param
                                                         : nullptr;
    if (slot == nullptr) {
      diags.error(param.key.loc,
                  "unknown @stochastic parameter '" + key + "': expected dist, clk or param");
    } else if (*slot != nullptr) {
      diags.error(param.key.loc, "@stochastic parameter '" + key + "' is given twice");
    } else if (!param.value) {
      diags.error(param.key.loc, "@stochastic parameter '" + key + "' needs a value");
    } else {
      *slot = &param;
    }
  }
  return keys;
}

void check_annotation(const ast::Annotation& annotation, const ast::AtomTypeDecl& atom,
                      Diagnostics& diags) {
  const Keys keys = collect_keys(annotation, diags);
  if (keys.clk == nullptr) {
    diags.error(annotation.loc, "@stochastic needs clk=<clock>: the clock the date is drawn from");
  } else if (index_of(atom.clocks, *keys.clk->value) < 0) {
    diags.error(keys.clk->value_loc, "undeclared clock '" + *keys.clk->value +
                                         "' in @stochastic: expected a clock of atom '" +
                                         atom.name.text + "'");
  }
  if (keys.dist == nullptr) {
    diags.error(annotation.loc, "@stochastic needs dist=<distribution>");
    return;
  }
  const Distribution* dist = find_distribution(*keys.dist->value);
  if (dist == nullptr) {
    diags.error(keys.dist->value_loc, "unknown distribution '" + *keys.dist->value +
                                          "': expected normal, exponential, gamma, chi2, "
                                          "uniform, lognormal, weibull or custom");
    return;
  }
  if (keys.param == nullptr) {
    diags.error(annotation.loc, "@stochastic needs param=\"...\" with the parameters of '" +
                                    std::string(dist->name) + "'");
    return;
  }
  check_params(*keys.param, *dist, atom, diags);
}

}  // namespace

void check_stochastic(const ast::PortDecl& port, const ast::AtomTypeDecl& atom,
                      Diagnostics& diags) {
  // A second @stochastic is reported as a redefined annotation; only the first one counts.
  for (const ast::Annotation& annotation : port.annotations) {
    if (annotation.name.text != "stochastic") continue;
    check_annotation(annotation, atom, diags);
    return;
  }
}

}  // namespace smcbip::bipc::detail
