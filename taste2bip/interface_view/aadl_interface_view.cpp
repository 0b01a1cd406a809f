// The AADL interface view reader: the declaration tree of InterfaceView.aadl (TASTE 1.3 and 2.x
// generations) interpreted as functions, interfaces and connections.
#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "taste2bip/interface_view/detail/aadl_properties.h"
#include "taste2bip/interface_view/detail/aadl_syntax.h"
#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip {
namespace {

using detail::aadl_key;
using detail::AadlClassifier;
using detail::AadlMember;
using detail::AadlPackage;
using detail::AadlReference;

/// Nested functions deeper than this are an error (and stop cyclic views).
constexpr int kMaxFunctionNesting = 16;

/// TASTE's period of a cyclic interface that gives none (the editor's default).
constexpr Milliseconds kDefaultCyclicPeriod = 1000;

struct Declared {
  const AadlClassifier* classifier = nullptr;
  const AadlPackage* package = nullptr;
};

/// A function's feature: whether it is provided, and the interface name it carries.
struct FeatureInfo {
  bool provided = false;
  std::string interface;
};

/// `pkg::Name` without `.impl`.
std::string without_implementation(const std::string& key) {
  const std::size_t colons = key.rfind("::");
  const std::size_t dot = key.find('.', colons == std::string::npos ? 0 : colons);
  return dot == std::string::npos ? key : key.substr(0, dot);
}

/// The last `::` segment of a reference (`DataView::T_Boolean` is `T_Boolean`).
std::string last_segment(const std::string& text) {
  const std::size_t colons = text.rfind("::");
  return colons == std::string::npos ? text : text.substr(colons + 2);
}

std::string without_taste_prefix(const std::string& feature) {
  const std::string key = aadl_key(feature.substr(0, 3));
  return key == "pi_" || key == "ri_" ? feature.substr(3) : feature;
}

bool has_word(const std::string& words, std::string_view word) {
  std::size_t start = 0;
  while (start <= words.size()) {
    std::size_t end = words.find(' ', start);
    if (end == std::string::npos) end = words.size();
    if (std::string_view(words).substr(start, end - start) == word) return true;
    start = end + 1;
  }
  return false;
}

class Reader {
 public:
  Reader(const detail::AadlFile& file, std::uint32_t file_index, detail::AadlErrors& errors)
      : file_(file), file_index_(file_index), errors_(errors), properties_(errors) {}

  InterfaceView run() {
    for (const AadlPackage& package : file_.packages) {
      for (const AadlClassifier& classifier : package.classifiers) {
        const std::string key = package.name.key + "::" + aadl_key(classifier.name.text);
        declared_.emplace(key, Declared{&classifier, &package});
      }
    }
    const Declared root = find_root();
    if (root.classifier == nullptr) return std::move(view_);
    read_functions(root, std::nullopt, 0);
    for (const Pending& pending : pending_connections_) read_connections(pending);
    return std::move(view_);
  }

 private:
  struct Pending {
    Declared implementation;
    std::optional<std::size_t> scope;
  };

  Declared find_root() {
    Declared found;
    for (const AadlPackage& package : file_.packages) {
      for (const AadlClassifier& classifier : package.classifiers) {
        if (classifier.category == "system" && classifier.implementation &&
            without_implementation(aadl_key(classifier.name.text)) == "interfaceview" &&
            (found.classifier == nullptr || package.name.key == "interfaceview::iv"))
          found = {&classifier, &package};
      }
    }
    if (found.classifier == nullptr && errors_.count() == 0) {
      const bipc::Location at = file_.packages.empty() ? bipc::Location{file_index_, 1, 1}
                                                       : file_.packages.front().name.at;
      errors_.error(at,
                    "expected a TASTE interface view: a SYSTEM IMPLEMENTATION "
                    "interfaceview.others (in PACKAGE interfaceview::IV)");
    }
    return found;
  }

  /// The declaration `ref` names, seen from `from` (an unqualified name is the package's own).
  const Declared* lookup(const std::string& key, const AadlPackage& from) const {
    const std::string full = key.find("::") == std::string::npos ? from.name.key + "::" + key : key;
    const auto found = declared_.find(full);
    return found == declared_.end() ? nullptr : &found->second;
  }

  void read_functions(const Declared& implementation, std::optional<std::size_t> scope, int depth) {
    pending_connections_.push_back({implementation, scope});
    for (const AadlMember& sub : implementation.classifier->subcomponents) {
      if (errors_.exhausted()) return;
      if (sub.words != "system") continue;
      if (depth >= kMaxFunctionNesting) {
        errors_.error(sub.name.at, "expected at most " + std::to_string(kMaxFunctionNesting) +
                                       " levels of nested functions");
        return;
      }
      const Declared* impl = lookup(sub.classifier.key, *implementation.package);
      const Declared* type =
          lookup(without_implementation(sub.classifier.key), *implementation.package);
      if (type == nullptr || type->classifier->category != "system") {
        errors_.error(sub.classifier.at.line == 0 ? sub.name.at : sub.classifier.at,
                      "expected the SYSTEM '" + sub.classifier.text + "' of function " +
                          sub.name.text + " to be declared in this view");
        continue;
      }
      if (has_function(scope, aadl_key(sub.name.text))) {
        errors_.error(sub.name.at, "expected one function " + sub.name.text +
                                       " at this level, got a second one");
        continue;
      }
      if (impl != nullptr && !on_stack_.insert(impl->classifier).second) {
        errors_.error(sub.classifier.at, "function " + sub.name.text + " contains itself");
        continue;
      }
      const std::size_t index = read_function(sub, *type, impl, scope);
      if (impl != nullptr) {
        read_functions(*impl, index, depth + 1);
        on_stack_.erase(impl->classifier);
      }
    }
  }

  bool has_function(std::optional<std::size_t> scope, const std::string& key) const {
    for (const Function& f : view_.functions) {
      if (f.parent == scope && aadl_key(f.name) == key) return true;
    }
    return false;
  }

  std::size_t read_function(const AadlMember& sub, const Declared& type, const Declared* impl,
                            std::optional<std::size_t> scope) {
    Function function;
    function.name = sub.name.text;
    function.parent = scope;
    function.at = type.classifier->name.at;
    if (const auto* language = find(type.classifier->properties, "source_language"))
      function.language = properties_.first_name(*language);
    // The 1.3 generation puts each PI's WCET on a subprogram subcomponent of the implementation.
    std::map<std::string, const AadlMember*> wcet_by_subprogram;
    if (impl != nullptr) {
      for (const AadlMember& member : impl->classifier->subcomponents) {
        if (member.words == "subprogram") wcet_by_subprogram[member.classifier.key] = &member;
        if (member.words == "data") function.context.push_back(context_parameter(member));
      }
    }
    const std::size_t index = view_.functions.size();
    auto& features = features_[index];
    for (const AadlMember& feature : type.classifier->features) {
      if (!has_word(feature.words, "access")) continue;
      const bool provided = has_word(feature.words, "provides");
      Interface interface = read_interface(function.name, feature, provided, type);
      if (provided) {
        const auto wcet = wcet_by_subprogram.find(feature.classifier.key);
        if (wcet != wcet_by_subprogram.end()) read_wcet(wcet->second->properties, interface);
      }
      features[aadl_key(feature.name.text)] = {provided, interface.name};
      (provided ? function.provided : function.required).push_back(std::move(interface));
    }
    view_.functions.push_back(std::move(function));
    return index;
  }

  ContextParameter context_parameter(const AadlMember& member) {
    ContextParameter parameter;
    parameter.name = member.name.text;
    parameter.type = last_segment(member.classifier.text);
    parameter.at = member.name.at;
    if (aadl_key(parameter.type) == "timer") {
      // A timer's FS_Default_Value is what the editor writes for every timer, not a duration:
      // the duration comes from the SDL's set_timer call.
      parameter.type = "Timer";
      return parameter;
    }
    if (const auto* value = find(member.properties, "fs_default_value"))
      parameter.value = properties_.string(*value).value_or("");
    return parameter;
  }

  Interface read_interface(const std::string& function, const AadlMember& feature, bool provided,
                           const Declared& type) {
    Interface interface;
    interface.at = feature.name.at;
    const auto& props = feature.properties;
    interface.name = without_taste_prefix(feature.name.text);
    if (const auto* name = find(props, "interfacename"))
      interface.name = properties_.string(*name).value_or(interface.name);
    if (const auto* kind = find(props, "rcmoperationkind")) {
      interface.kind = properties_.kind(*kind).value_or(InterfaceKind::Any);
    } else if (provided) {
      errors_.error(feature.name.at,
                    "expected Taste::RCMoperationKind on provided interface " + feature.name.text);
    }
    if (const auto* period = find(props, "rcmperiod")) interface.period = properties_.time(*period);
    if (const auto* deadline = find(props, "deadline"))
      interface.deadline = properties_.time(*deadline);
    if (const auto* offset = find(props, "dispatch_offset"))
      interface.dispatch_offset = properties_.time(*offset);
    if (provided && interface.kind == InterfaceKind::Cyclic && !interface.period) {
      interface.period = kDefaultCyclicPeriod;
      view_.assumptions.push_back(
          {"cyclic interface " + function + "." + interface.name + " has no period: 1000 ms",
           feature.name.at});
    }
    // The subprogram: a PI's classifier is its own; an RI's names the callee's, so its own
    // SUBPROGRAM RI_x is looked up in the function's package (2.x) or interfaceview::FV::<F> (1.3).
    const Declared* subprogram = nullptr;
    const std::string feature_key = aadl_key(feature.name.text);
    if (!provided) {
      subprogram = lookup(feature_key, *type.package);
      if (subprogram == nullptr)
        subprogram = lookup(
            "interfaceview::fv::" + aadl_key(type.classifier->name.text) + "::" + feature_key,
            *type.package);
    }
    if (subprogram == nullptr && !feature.classifier.key.empty())
      subprogram = lookup(without_implementation(feature.classifier.key), *type.package);
    if (subprogram != nullptr && subprogram->classifier->category == "subprogram") {
      read_parameters(*subprogram->classifier, interface);
      if (provided) {
        if (const auto* queue = find(subprogram->classifier->properties, "associated_queue_size"))
          interface.queue_size = properties_.count(*queue);
      }
    }
    if (provided && !feature.classifier.key.empty()) {
      const Declared* impl = lookup(feature.classifier.key, *type.package);
      if (impl != nullptr) read_wcet(impl->classifier->properties, interface);
    }
    return interface;
  }

  void read_parameters(const AadlClassifier& subprogram, Interface& interface) {
    for (const AadlMember& feature : subprogram.features) {
      if (!has_word(feature.words, "parameter")) continue;
      Parameter parameter;
      parameter.name = feature.name.text;
      parameter.at = feature.name.at;
      // DataView.aadl spells ASN.1's '-' as '_': the type keeps the AADL spelling.
      parameter.type = last_segment(feature.classifier.text);
      if (feature.words == "in parameter") {
        parameter.direction = Parameter::Direction::In;
      } else if (feature.words == "out parameter") {
        parameter.direction = Parameter::Direction::Out;
      } else {
        errors_.error(feature.name.at,
                      "expected an IN or OUT PARAMETER, got '" + feature.words + "'");
        continue;
      }
      if (parameter.type.empty())
        errors_.error(feature.name.at, "expected the data type of parameter " + parameter.name);
      interface.parameters.push_back(std::move(parameter));
    }
  }

  void read_wcet(const std::vector<detail::AadlProperty>& props, Interface& interface) {
    if (const auto* wcet = find(props, "compute_execution_time")) {
      if (auto range = properties_.time_range(*wcet)) {
        interface.wcet_low = range->first;
        interface.wcet_high = range->second;
      }
    }
  }

  static const detail::AadlProperty* find(const std::vector<detail::AadlProperty>& props,
                                          std::string_view name) {
    const detail::AadlProperty* found = nullptr;
    for (const auto& p : props) {
      if (last_segment(p.key) == name) found = &p;  // the last association wins
    }
    return found;
  }

  /// `C.PI_x -> D.RI_y` (or a parent's own `PI_x`): the arrow goes from provider to requirer, so
  /// `from` is the destination.
  void read_connections(const Pending& pending) {
    std::set<std::string> subprogram_calls;
    for (const AadlMember& sub : pending.implementation.classifier->subcomponents) {
      if (sub.words == "subprogram") subprogram_calls.insert(aadl_key(sub.name.text));
    }
    for (const AadlMember& member : pending.implementation.classifier->connections) {
      if (errors_.exhausted()) return;
      // The 1.3 generation's `OpToPICnx_*` joins a PI to its implementation subprogram.
      if (subprogram_calls.count(member.source.key) > 0 ||
          subprogram_calls.count(member.destination.key) > 0)
        continue;
      Connection connection;
      connection.at = member.name.at;
      if (!endpoint(member.destination, pending.scope, connection.from) ||
          !endpoint(member.source, pending.scope, connection.to))
        continue;
      // Between two functions of one level the provider comes first; a delegation joins a
      // parent's interface to a child's of the same side.
      const bool siblings = member.source.text.find('.') != std::string::npos &&
                            member.destination.text.find('.') != std::string::npos;
      if (siblings && (!connection.to.provided || connection.from.provided)) {
        errors_.error(member.source.at,
                      "expected a provided interface before '->' and a required one after it, "
                      "got " +
                          std::string(connection.to.provided ? "provided" : "required") + " '" +
                          member.source.text + "' -> " +
                          (connection.from.provided ? "provided" : "required") + " '" +
                          member.destination.text + "'");
        continue;
      }
      view_.connections.push_back(std::move(connection));
    }
  }

  bool endpoint(const AadlReference& ref, std::optional<std::size_t> scope, Endpoint& out) {
    const std::size_t dot = ref.text.find('.');
    std::optional<std::size_t> function;
    std::string feature = ref.text;
    if (dot == std::string::npos) {
      if (!scope) {
        errors_.error(ref.at, "expected Function.Interface, got '" + ref.text + "'");
        return false;
      }
      function = scope;
    } else {
      const std::string component = aadl_key(ref.text.substr(0, dot));
      feature = ref.text.substr(dot + 1);
      for (std::size_t i = 0; i < view_.functions.size(); ++i) {
        if (view_.functions[i].parent == scope && aadl_key(view_.functions[i].name) == component)
          function = i;
      }
      if (!function) {
        errors_.error(ref.at,
                      "expected a function of this level, got '" + ref.text.substr(0, dot) + "'");
        return false;
      }
    }
    const auto& features = features_[*function];
    const auto found = features.find(aadl_key(feature));
    if (found == features.end()) {
      errors_.error(ref.at, "expected an interface of function " + view_.functions[*function].name +
                                ", got '" + feature + "'");
      return false;
    }
    out.function = view_.functions[*function].name;
    out.interface = found->second.interface;
    out.provided = found->second.provided;
    return true;
  }

  const detail::AadlFile& file_;
  std::uint32_t file_index_;
  detail::AadlErrors& errors_;
  detail::AadlPropertyValues properties_;
  std::unordered_map<std::string, Declared> declared_;
  std::unordered_map<std::size_t, std::unordered_map<std::string, FeatureInfo>> features_;
  std::set<const AadlClassifier*> on_stack_;
  std::vector<Pending> pending_connections_;
  InterfaceView view_;
};

}  // namespace

InterfaceView read_aadl_interface_view(const std::string& text, std::uint32_t file,
                                       bipc::Diagnostics& diags) {
  detail::AadlErrors errors(diags);
  const std::vector<detail::AadlToken> tokens = detail::lex_aadl(text, file, errors);
  const detail::AadlFile syntax = detail::parse_aadl(tokens, errors);
  return Reader(syntax, file, errors).run();
}

}  // namespace smcbip::taste2bip
