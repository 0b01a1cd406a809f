// The reference engine's text trace format.
#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

std::string count(std::size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n > 1 ? "s" : "");
}

}  // namespace

std::string enabled_summary(std::size_t interactions, std::size_t internals,
                            std::size_t externals) {
  std::string text;
  auto add = [&](std::size_t n, const char* what) {
    if (n == 0) return;
    if (!text.empty()) text += " and ";
    text += count(n, what);
  };
  add(interactions, "interaction");
  add(internals, "internal port");
  add(externals, "external port");
  return text + ":";
}

std::string item_text(const Runtime& runtime, const Item& item, bool with_interval) {
  std::string text;
  if (item.kind == Item::Kind::Interaction) {
    const InteractionValue& value = runtime.values()[item.value];
    text = runtime.layout().connector_names[value.connector] + ": " + format_ports(runtime, value);
  } else {
    const auto& system = runtime.system();
    text = runtime.layout().atom_names[item.atom] + "." +
           system.atom_types[system.atoms[item.atom].type].ports[item.port].name;
  }
  if (with_interval) text += " " + format_interval(item.constraint.interval);
  return text;
}

void write_state(std::ostream& out, const Runtime& runtime, std::uint64_t step) {
  std::size_t counts[3] = {0, 0, 0};
  for (const Item& item : runtime.items()) ++counts[static_cast<int>(item.kind)];
  out << kEnginePrefix << "state #" << step << " and global time "
      << format_time(runtime.state().now) << ": "
      << enabled_summary(counts[0], counts[1], counts[2]) << "\n";
  std::size_t index = 0;
  for (const Item& item : runtime.items()) {
    out << kEnginePrefix << "  [" << index++ << "] " << item_text(runtime, item, true) << "\n";
  }
}

}  // namespace smcbip::engines
