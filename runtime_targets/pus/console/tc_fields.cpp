// Which field options each telecommand subtype takes, and the refusal of the others.
#include "console/detail/tc_fields.h"

#include <array>

namespace smcbip::pus::console {
namespace {

/// A field option of TcWords: its name and whether it was given.
struct GivenField {
  const char* name;
  bool given;
};

std::array<GivenField, 9> given_fields(const TcWords& w) {
  return {{{"--sid", !w.sids.empty()},
           {"--event", !w.events.empty()},
           {"--pmon", !w.pmons.empty()},
           {"--param", !w.params.empty()},
           {"--function", w.function.has_value()},
           {"--arg", !w.args.empty()},
           {"--rate", w.rate.has_value()},
           {"--release", !w.releases.empty()},
           {"--action", !w.actions.empty()}}};
}

/// The field options of a subtype, as --help writes them.
std::string fields_of(const MessageType& type) {
  switch (type.shape) {
    case Shape::IdList:
      switch (type.service) {
        case 3:
          return "--sid ID...";
        case 12:
          return "--pmon ID...";
        case 20:
          return "--param ID...";
        default:
          return "--event ID...";
      }
    case Shape::FunctionCall:
      return "--function ID [--arg ID=VALUE...]";
    case Shape::ParameterValues:
      return "--param ID=VALUE...";
    case Shape::TimeReportRate:
      return "--rate N";
    case Shape::Activities:
      return type.service == 11 ? "--release TIME=HEX..." : "--action EVENT=HEX...";
    default:
      return "no fields";
  }
}

std::string type_name(const MessageType& type) {
  return "TC[" + std::to_string(type.service) + "," + std::to_string(type.subtype) + "]";
}

}  // namespace

namespace detail {

void check_fields(const MessageType& type, const TcWords& words) {
  const std::string accepted = fields_of(type);
  for (const GivenField& field : given_fields(words)) {
    if (!field.given) continue;
    const std::string name = field.name;
    // An option is accepted when its name stands in the subtype's field list as a whole word.
    const auto at = accepted.find(name + " ");
    if (at == std::string::npos && accepted != name) {
      throw TcSyntaxError(name, "",
                          name + ": " + type_name(type) + " (" + type.name +
                              ") takes no such field; expected " + accepted);
    }
  }
  const bool needs_function = type.shape == Shape::FunctionCall && !words.function;
  const bool needs_rate = type.shape == Shape::TimeReportRate && !words.rate;
  if (needs_function || needs_rate) {
    const std::string name = needs_function ? "--function" : "--rate";
    throw TcSyntaxError(
        name, "",
        type_name(type) + " (" + type.name + ") expected " + accepted + ", got no " + name);
  }
}

}  // namespace detail
}  // namespace smcbip::pus::console
