// Reads the XML interface view of the TASTE editor (`interfaceview.xml`, versions 1.0 to 1.3).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip {
namespace {

/// The editor's period for a cyclic interface that names none (spacecreator's default).
constexpr Milliseconds kDefaultCyclicPeriod = 1000.0;

/// Functions nest at most this deep: the reader recurses once per level, and no design comes
/// near it (the examples nest three levels).
constexpr std::size_t kMaxNesting = 200;

/// Maps pugixml's byte offsets to 1-based line:column (columns count bytes).
class LineIndex {
 public:
  LineIndex(const std::string& text, std::uint32_t file) : file_(file), size_(text.size()) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') starts_.push_back(i + 1);
    }
  }

  /// An offset past the end (pugixml may give one on truncated text) is the end of the text.
  bipc::Location at(std::ptrdiff_t offset) const {
    const std::size_t off = offset < 0 ? 0 : std::min(static_cast<std::size_t>(offset), size_);
    const auto next = std::upper_bound(starts_.begin(), starts_.end(), off);
    const auto line = static_cast<std::size_t>(next - starts_.begin());  // >= 1
    return {file_, static_cast<std::uint32_t>(line),
            static_cast<std::uint32_t>(off - starts_[line - 1] + 1)};
  }

  /// Where an element starts: pugixml gives the offset of its name, one past the `<`.
  bipc::Location at(const pugi::xml_node& node) const {
    const std::ptrdiff_t offset = node.offset_debug();
    return at(offset > 0 ? offset - 1 : 0);
  }

 private:
  std::uint32_t file_;
  std::size_t size_;
  std::vector<std::size_t> starts_;
};

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

/// What pugixml's status means for the writer of the file.
std::string syntax_message(const pugi::xml_parse_result& result) {
  switch (result.status) {
    case pugi::status_no_document_element:
      return "expected an <InterfaceView> element, got no element";
    case pugi::status_end_element_mismatch:
      return "malformed XML: expected the closing tag of the open element";
    case pugi::status_bad_attribute:
      return "malformed XML: expected an attribute `name=\"value\"`";
    case pugi::status_bad_start_element:
      return "malformed XML: expected `>` or `/>` closing the start tag";
    case pugi::status_bad_end_element:
      return "malformed XML: expected `</name>`";
    case pugi::status_unrecognized_tag:
      return "malformed XML: expected an element name after `<`";
    default:
      return std::string("malformed XML: ") + result.description();
  }
}

class Reader {
 public:
  Reader(const std::string& text, std::uint32_t file, bipc::Diagnostics& diags)
      : lines_(text, file), diags_(diags) {}

  void read_root(const pugi::xml_node& root) {
    for (const pugi::xml_node& child : root.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view tag = child.name();
      if (tag == "Function") {
        read_function(child, std::nullopt);
      } else if (tag == "Connection") {
        read_connection(child);
      }
      // Layer, Comment and the like are the editor's presentation.
    }
  }

  InterfaceView view;

 private:
  /// A required attribute; a located error naming it when it is absent or empty.
  std::optional<std::string> required(const pugi::xml_node& node, const char* attribute,
                                      const std::string& what) {
    const pugi::xml_attribute a = node.attribute(attribute);
    if (a.empty() || a.value()[0] == '\0') {
      diags_.error(lines_.at(node), what + " without " + attribute + ": expected attribute `" +
                                        attribute + "=\"...\"`");
      return std::nullopt;
    }
    return std::string(a.value());
  }

  /// A non-negative number of milliseconds, when the attribute is there.
  std::optional<Milliseconds> duration(const pugi::xml_node& node, const char* attribute) {
    const pugi::xml_attribute a = node.attribute(attribute);
    if (a.empty()) return std::nullopt;
    const char* begin = a.value();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    const bool blank_tail =
        end != begin &&
        std::all_of(static_cast<const char*>(end), begin + std::strlen(begin),
                    [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
    if (end == begin || !blank_tail || errno == ERANGE || !std::isfinite(value) || value < 0) {
      diags_.error(lines_.at(node), std::string("expected `") + attribute +
                                        "` to be a non-negative number of ms, got \"" + a.value() +
                                        "\"");
      return std::nullopt;
    }
    return value;
  }

  std::optional<std::uint32_t> count(const pugi::xml_node& node, const char* attribute) {
    const pugi::xml_attribute a = node.attribute(attribute);
    if (a.empty()) return std::nullopt;
    const std::string_view text = a.value();
    std::uint64_t value = 0;
    bool ok = !text.empty() && text.size() <= 10;
    for (char c : text) {
      if (c < '0' || c > '9') ok = false;
      if (ok) value = value * 10 + static_cast<std::uint64_t>(c - '0');
    }
    if (!ok || value > 0xFFFFFFFFu) {
      diags_.error(lines_.at(node), std::string("expected `") + attribute +
                                        "` to be a non-negative integer, got \"" + a.value() +
                                        "\"");
      return std::nullopt;
    }
    return static_cast<std::uint32_t>(value);
  }

  void read_function(const pugi::xml_node& node, std::optional<std::size_t> parent) {
    Function function;
    function.at = lines_.at(node);
    function.parent = parent;
    if (auto name = required(node, "name", "function")) function.name = *name;
    const pugi::xml_attribute is_type = node.attribute("is_type");
    if (!is_type.empty()) {
      if (same_ignoring_case(is_type.value(), "YES")) {
        function.is_type = true;
      } else if (!same_ignoring_case(is_type.value(), "NO")) {
        diags_.error(function.at, std::string("expected `is_type` to be YES or NO, got \"") +
                                      is_type.value() + "\"");
      }
    }
    function.language = node.attribute("language").value();
    if (function.language.empty()) function.language = implementation_language(node);

    const std::size_t depth = parent ? depth_[*parent] + 1 : 0;
    if (depth >= kMaxNesting) {
      diags_.error(function.at, "function nested " + std::to_string(depth + 1) +
                                    " levels deep: expected at most " +
                                    std::to_string(kMaxNesting));
      return;
    }
    const std::size_t index = view.functions.size();
    view.functions.push_back(std::move(function));
    depth_.push_back(depth);
    // Children are read after the parent's slot exists, so they can name it by index.
    for (const pugi::xml_node& child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view tag = child.name();
      if (tag == "Provided_Interface" || tag == "Required_Interface") {
        const bool provided = tag == "Provided_Interface";
        Interface iface = read_interface(child, provided, view.functions[index].name);
        auto& list = provided ? view.functions[index].provided : view.functions[index].required;
        list.push_back(std::move(iface));
      } else if (tag == "ContextParameter") {
        ContextParameter parameter;
        parameter.at = lines_.at(child);
        if (auto name = required(child, "name", "context parameter")) parameter.name = *name;
        if (auto type = required(child, "type", "context parameter")) parameter.type = *type;
        parameter.value = child.attribute("value").value();
        view.functions[index].context.push_back(std::move(parameter));
      } else if (tag == "Function") {
        read_function(child, index);
      } else if (tag == "Connection") {
        read_connection(child);
      }
      // Property, Implementations (read above), comments: presentation and code generation.
    }
  }

  /// The language of the function's default implementation (views without a `language=`).
  static std::string implementation_language(const pugi::xml_node& node) {
    const std::string_view wanted = node.attribute("default_implementation").value();
    std::string first;
    for (const pugi::xml_node& impl : node.child("Implementations").children("Implementation")) {
      if (first.empty()) first = impl.attribute("language").value();
      if (!wanted.empty() && wanted == impl.attribute("name").value()) {
        return impl.attribute("language").value();
      }
    }
    return first;
  }

  Interface read_interface(const pugi::xml_node& node, bool provided, const std::string& function) {
    Interface iface;
    iface.at = lines_.at(node);
    const std::string what = provided ? "provided interface" : "required interface";
    if (auto name = required(node, "name", what)) iface.name = *name;
    const pugi::xml_attribute kind = node.attribute("kind");
    if (kind.empty() || kind.value()[0] == '\0') {
      if (provided) {
        diags_.error(iface.at,
                     "provided interface without kind: expected attribute "
                     "`kind=\"Cyclic|Sporadic|Protected|Unprotected\"`");
      }
    } else if (same_ignoring_case(kind.value(), "Cyclic")) {
      iface.kind = InterfaceKind::Cyclic;
    } else if (same_ignoring_case(kind.value(), "Sporadic")) {
      iface.kind = InterfaceKind::Sporadic;
    } else if (same_ignoring_case(kind.value(), "Protected")) {
      iface.kind = InterfaceKind::Protected;
    } else if (same_ignoring_case(kind.value(), "Unprotected")) {
      iface.kind = InterfaceKind::Unprotected;
    } else if (!provided && same_ignoring_case(kind.value(), "Any")) {
      iface.kind = InterfaceKind::Any;
    } else {
      diags_.error(iface.at, std::string("expected kind Cyclic, Sporadic, Protected or "
                                         "Unprotected, got \"") +
                                 kind.value() + "\"");
    }

    const std::optional<Milliseconds> period = duration(node, "period");
    const std::optional<Milliseconds> miat = duration(node, "miat");
    // A sporadic interface's period is its minimal inter-arrival time.
    iface.period = iface.kind == InterfaceKind::Sporadic && miat ? miat : period;
    iface.deadline = duration(node, "deadline");
    iface.dispatch_offset = duration(node, "dispatch_offset");
    iface.queue_size = count(node, "queue_size");
    iface.wcet_low = duration(node, "wcet");
    iface.wcet_high = iface.wcet_low;
    if (provided && iface.kind == InterfaceKind::Cyclic && !iface.period &&
        node.attribute("period").empty()) {
      iface.period = kDefaultCyclicPeriod;
      view.assumptions.push_back(
          {"cyclic interface " + function + "." + iface.name + " has no period: 1000 ms",
           iface.at});
    }

    for (const pugi::xml_node& child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view tag = child.name();
      if (tag != "Input_Parameter" && tag != "Output_Parameter") continue;
      Parameter parameter;
      parameter.at = lines_.at(child);
      parameter.direction =
          tag == "Input_Parameter" ? Parameter::Direction::In : Parameter::Direction::Out;
      if (auto name = required(child, "name", "parameter")) parameter.name = *name;
      if (auto type = required(child, "type", "parameter")) parameter.type = *type;
      iface.parameters.push_back(std::move(parameter));
    }
    return iface;
  }

  std::optional<Endpoint> read_endpoint(const pugi::xml_node& connection, const char* tag) {
    const pugi::xml_node node = connection.child(tag);
    const std::string what = std::string("connection ") + tag;
    if (node.empty()) {
      diags_.error(lines_.at(connection), std::string("connection without <") + tag +
                                              ">: expected <" + tag +
                                              " func_name=\"...\" ri_name|pi_name=\"...\"/>");
      return std::nullopt;
    }
    Endpoint endpoint;
    auto function = required(node, "func_name", what);
    const pugi::xml_attribute ri = node.attribute("ri_name");
    const pugi::xml_attribute pi = node.attribute("pi_name");
    if (ri.empty() == pi.empty()) {
      diags_.error(lines_.at(node), what + (ri.empty() ? " without" : " with both") +
                                        " ri_name and pi_name: expected exactly one of them");
      return std::nullopt;
    }
    endpoint.provided = !pi.empty();
    endpoint.interface = endpoint.provided ? pi.value() : ri.value();
    if (endpoint.interface.empty()) {
      diags_.error(lines_.at(node), what + " with an empty interface name: expected `" +
                                        (endpoint.provided ? "pi_name" : "ri_name") + "=\"...\"`");
      return std::nullopt;
    }
    if (!function) return std::nullopt;
    endpoint.function = *function;
    return endpoint;
  }

  void read_connection(const pugi::xml_node& node) {
    std::optional<Endpoint> from = read_endpoint(node, "Source");
    std::optional<Endpoint> to = read_endpoint(node, "Target");
    if (!from || !to) return;
    view.connections.push_back({std::move(*from), std::move(*to), lines_.at(node)});
  }

  LineIndex lines_;
  bipc::Diagnostics& diags_;
  std::vector<std::size_t> depth_;  // per function read, its nesting level
};

}  // namespace

InterfaceView read_xml_interface_view(const std::string& text, std::uint32_t file,
                                      bipc::Diagnostics& diags) {
  Reader reader(text, file, diags);
  pugi::xml_document document;
  // UTF-8 as is: a conversion would shift the offsets that locate the diagnostics.
  const pugi::xml_parse_result result =
      document.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  LineIndex lines(text, file);
  if (!result) {
    // pugixml points at the last character when the text stops inside an element.
    if (result.status == pugi::status_end_element_mismatch &&
        static_cast<std::size_t>(result.offset) + 1 >= text.size()) {
      diags.error(lines.at(static_cast<std::ptrdiff_t>(text.size())),
                  "malformed XML: the text ends inside an element: expected its closing tag");
      return {};
    }
    diags.error(lines.at(result.offset), syntax_message(result));
    return {};
  }
  const pugi::xml_node root = document.document_element();
  if (std::string_view(root.name()) != "InterfaceView") {
    diags.error(lines.at(root),
                std::string("expected an <InterfaceView> element, got <") + root.name() + ">");
    return {};
  }
  reader.read_root(root);
  return std::move(reader.view);
}

}  // namespace smcbip::taste2bip
