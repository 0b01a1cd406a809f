#include "taste2bip/translate/detail/package_parts.h"

#include <cmath>

namespace smcbip::taste2bip::detail {

namespace {

std::vector<BipParameter> positional(const std::vector<std::string>& types) {
  std::vector<BipParameter> out;
  for (std::size_t i = 0; i < types.size(); ++i) out.push_back({"a" + std::to_string(i), types[i]});
  return out;
}

std::string copies(std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string a = "a" + std::to_string(i);
    out += "r." + a + " = s." + a + "; ";
  }
  return out;
}

}  // namespace

bool OnceList::add(const std::string& key, std::string text) {
  if (!keys_.insert(key).second) return false;
  texts_.push_back(std::move(text));
  return true;
}

std::string OnceList::text() const {
  std::string out;
  for (const std::string& t : texts_) out += t;
  return out;
}

std::int64_t whole_milliseconds(double ms, const std::string& what, PackageParts& parts) {
  const double up = std::ceil(ms);
  if (up != ms) {
    parts.report.push_back(what + ": " + std::to_string(ms) + " ms rounded up to " +
                           std::to_string(static_cast<std::int64_t>(up)) + " ms");
  }
  return static_cast<std::int64_t>(up);
}

std::string use_port_type(const std::vector<std::string>& types, PackageParts& parts) {
  const std::string name = port_type_name(types);
  parts.port_types.add(name, port_type(name, positional(types)));
  return name;
}

std::string use_connector_type(const std::vector<std::string>& types, int extra,
                               PackageParts& parts) {
  const std::string port = use_port_type(types, parts);
  use_port_type({}, parts);
  const std::string base = types.empty() ? "Sync" : "Call_" + port.substr(5);
  const std::string name = extra == 0 ? base : base + "_" + std::to_string(extra + 2);
  std::string parameters = port + " s, " + port + " r", ends = "s r";
  for (int i = 0; i < extra; ++i) {
    const std::string w = "w" + std::to_string(i);
    parameters += ", Port " + w;
    ends += " " + w;
  }
  std::string text = "  connector type " + name + "(" + parameters + ")\n    define " + ends + "\n";
  if (!types.empty()) text += "    on " + ends + " down { " + copies(types.size()) + "}\n";
  parts.connector_types.add(name, text + "  end\n");
  return name;
}

std::string use_lone_connector_type(const std::vector<std::string>& types, PackageParts& parts) {
  const std::string port = use_port_type(types, parts);
  const std::string name = "Alone_" + port;
  parts.connector_types.add(name,
                            "  connector type " + name + "(" + port + " s)\n    define s\n  end\n");
  return name;
}

}  // namespace smcbip::taste2bip::detail
