// Which field options each telecommand subtype takes, and the refusal of the others.
#include "console/detail/tc_fields.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace smcbip::pus::console {
namespace {

/// A field option of TcWords: its name and whether it was given.
struct GivenField {
  const char* name;
  bool given;
};

std::array<GivenField, 15> given_fields(const TcWords& w) {
  return {{{"--sid", !w.sids.empty()},
           {"--event", !w.events.empty()},
           {"--pmon", !w.pmons.empty()},
           {"--param", !w.params.empty()},
           {"--function", w.function.has_value()},
           {"--arg", !w.args.empty()},
           {"--rate", w.rate.has_value()},
           {"--release", !w.releases.empty()},
           {"--action", !w.actions.empty()},
           {"--repo", w.repo.has_value()},
           {"--file", w.file.has_value()},
           {"--size", w.size.has_value()},
           {"--operation", w.operation.has_value()},
           {"--to-repo", w.to_repo.has_value()},
           {"--to-file", w.to_file.has_value()}}};
}

/// The field options a subtype takes, those it requires, and its syntax as --help writes it.
struct Fields {
  std::vector<std::string> options;
  std::vector<std::string> required;
  std::string syntax;
};

Fields id_list_fields(std::uint8_t service) {
  switch (service) {
    case 3:
      return {{"--sid"}, {}, "--sid ID..."};
    case 12:
      return {{"--pmon"}, {}, "--pmon ID..."};
    case 20:
      return {{"--param"}, {}, "--param ID..."};
    default:
      return {{"--event"}, {}, "--event ID..."};
  }
}

Fields file_fields(std::uint8_t subtype) {
  switch (subtype) {
    case 1:
      return {{"--repo", "--file", "--size"},
              {"--file", "--size"},
              "[--repo PATH] --file NAME --size N"};
    case 14:
      return {{"--operation", "--repo", "--file", "--to-repo", "--to-file"},
              {"--operation", "--file", "--to-file"},
              "--operation ID [--repo PATH] --file NAME [--to-repo PATH] --to-file NAME"};
    default:
      return {{"--repo", "--file"}, {"--file"}, "[--repo PATH] --file NAME"};
  }
}

Fields fields_of(const MessageType& type) {
  switch (type.shape) {
    case Shape::IdList:
      return id_list_fields(type.service);
    case Shape::FunctionCall:
      return {{"--function", "--arg"}, {"--function"}, "--function ID [--arg ID=VALUE...]"};
    case Shape::ParameterValues:
      return {{"--param"}, {}, "--param ID=VALUE..."};
    case Shape::TimeReportRate:
      return {{"--rate"}, {"--rate"}, "--rate N"};
    case Shape::Activities:
      return type.service == 11 ? Fields{{"--release"}, {}, "--release TIME=HEX..."}
                                : Fields{{"--action"}, {}, "--action EVENT=HEX..."};
    case Shape::FileRequest:
      return file_fields(type.subtype);
    default:
      return {{}, {}, "no fields"};
  }
}

std::string type_name(const MessageType& type) {
  return "TC[" + std::to_string(type.service) + "," + std::to_string(type.subtype) + "]";
}

}  // namespace

namespace detail {

void check_fields(const MessageType& type, const TcWords& words) {
  const Fields fields = fields_of(type);
  const auto takes = [&](const std::string& name) {
    return std::find(fields.options.begin(), fields.options.end(), name) != fields.options.end();
  };
  for (const GivenField& field : given_fields(words)) {
    if (field.given && !takes(field.name)) {
      throw TcSyntaxError(field.name, "",
                          std::string(field.name) + ": " + type_name(type) + " (" + type.name +
                              ") takes no such field; expected " + fields.syntax);
    }
  }
  for (const GivenField& field : given_fields(words)) {
    if (!field.given && std::find(fields.required.begin(), fields.required.end(), field.name) !=
                            fields.required.end()) {
      throw TcSyntaxError(field.name, "",
                          type_name(type) + " (" + type.name + ") expected " + fields.syntax +
                              ", got no " + field.name);
    }
  }
}

}  // namespace detail
}  // namespace smcbip::pus::console
