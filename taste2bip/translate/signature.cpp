#include "taste2bip/translate/signature.h"

#include <algorithm>
#include <set>

#include "taste2bip/names.h"

namespace smcbip::taste2bip {

namespace {

std::optional<InterfaceKind> reached_kind(const InterfaceView& view, const Function& function,
                                          const Interface& required) {
  for (const Connection& c : view.connections) {
    if (c.from.function != function.name || c.from.interface != required.name) continue;
    for (const Function& callee : view.functions) {
      if (callee.name != c.to.function) continue;
      for (const Interface& p : callee.provided) {
        if (p.name == c.to.interface) return p.kind;
      }
    }
  }
  return std::nullopt;
}

SignalInterface signal_interface(const Interface& source, InterfaceKind kind,
                                 const asn1::DataView& data, bipc::Diagnostics& diags) {
  SignalInterface out;
  out.name = bip_identifier(source.name);
  out.data_prefix = out.name;
  out.kind = kind;
  out.source = &source;
  out.at = source.at;
  for (const Parameter& p : source.parameters) {
    SignalParameter parameter;
    parameter.name = bip_identifier(p.name);
    parameter.asn1_type = p.type;
    parameter.out = p.direction == Parameter::Direction::Out;
    parameter.at = p.at;
    if (auto leaves = leaves_of(data, p.type, p.at, diags)) parameter.leaves = std::move(*leaves);
    out.parameters.push_back(std::move(parameter));
  }
  return out;
}

std::string port_declaration(const SignalInterface& i, bool out, const std::string& port) {
  std::string names;
  for (const std::string& n : i.data_names(out)) names += (names.empty() ? "" : ", ") + n;
  return "    export port " + port_type_name(i.data_types(out)) + " " + i.name + "_" + port + "(" +
         names + ")\n";
}

std::string data_declarations(const SignalInterface& i) {
  std::string text;
  for (bool out : {false, true}) {
    const auto names = i.data_names(out);
    const auto types = i.data_types(out);
    for (std::size_t k = 0; k < names.size(); ++k) {
      text += "    data " + types[k] + " " + names[k] + "\n";
    }
  }
  return text;
}

/// Data and ports share the atom's names: a parameter named `result` of interface `get` would
/// give data `get_result`, the name of get's result port. Such an interface's data take the
/// prefix `<name>_data` instead.
void keep_data_apart_from_ports(FunctionSignature& f) {
  std::set<std::string> ports;
  for (const SignalInterface& i : f.provided) {
    ports.insert({i.name + "_in", i.name + "_return"});
  }
  for (const SignalInterface& i : f.required) ports.insert({i.name + "_out", i.name + "_result"});
  for (auto* list : {&f.provided, &f.required}) {
    for (SignalInterface& i : *list) {
      const auto in = i.data_names(false), out = i.data_names(true);
      const auto clash = [&](const std::string& n) { return ports.count(n) > 0; };
      if (std::any_of(in.begin(), in.end(), clash) || std::any_of(out.begin(), out.end(), clash)) {
        i.data_prefix = (i.data_prefix.empty() ? i.name : i.data_prefix) + "_data";
      }
    }
  }
}

}  // namespace

void separate_data_names(FunctionSignature& f) {
  for (SignalInterface& r : f.required) {
    for (const SignalInterface& p : f.provided) {
      if (p.name == r.name) r.data_prefix = r.name + "_ri";
    }
  }
  keep_data_apart_from_ports(f);
}

std::vector<std::string> SignalInterface::data_names(bool out) const {
  std::vector<std::string> names;
  for (const SignalParameter& p : parameters) {
    if (p.out != out) continue;
    for (const Leaf& leaf : p.leaves) names.push_back(leaf_name(data_of(p), leaf));
  }
  return names;
}

std::vector<std::string> SignalInterface::data_types(bool out) const {
  std::vector<std::string> types;
  for (const SignalParameter& p : parameters) {
    if (p.out != out) continue;
    for (const Leaf& leaf : p.leaves) types.push_back(leaf.type);
  }
  return types;
}

FunctionSignature function_signature(const InterfaceView& view, std::size_t index,
                                     const asn1::DataView& data, bipc::Diagnostics& diags) {
  const Function& f = view.functions[index];
  FunctionSignature out;
  out.name = bip_identifier(f.name);
  out.language = f.language;
  out.source = &f;
  for (const Interface& p : f.provided) {
    out.provided.push_back(signal_interface(p, p.kind, data, diags));
  }
  for (const Interface& r : f.required) {
    const InterfaceKind kind = reached_kind(view, f, r).value_or(InterfaceKind::Any);
    out.required.push_back(signal_interface(r, kind, data, diags));
  }
  separate_data_names(out);
  for (const ContextParameter& c : f.context) {
    if (c.type == "Timer") {
      out.context_timers.push_back(bip_identifier(c.name));
      continue;
    }
    ContextValue value{bip_identifier(c.name), c.type, c.value, {}, c.at};
    if (auto leaves = leaves_of(data, c.type, c.at, diags)) value.leaves = std::move(*leaves);
    out.context.push_back(std::move(value));
  }
  return out;
}

std::string interface_declarations(const FunctionSignature& function) {
  std::string text;
  for (const SignalInterface& p : function.provided) text += data_declarations(p);
  for (const SignalInterface& r : function.required) text += data_declarations(r);
  for (const SignalInterface& p : function.provided) {
    text += port_declaration(p, false, "in") + port_declaration(p, true, "return");
  }
  for (const SignalInterface& r : function.required) {
    text += port_declaration(r, false, "out");
    if (r.synchronous()) text += port_declaration(r, true, "result");
  }
  return text;
}

void collect_port_types(const FunctionSignature& function,
                        std::vector<std::pair<std::string, std::vector<std::string>>>& into) {
  auto add = [&](const std::vector<std::string>& types) {
    const std::string name = port_type_name(types);
    const bool known = std::any_of(into.begin(), into.end(),
                                   [&](const auto& entry) { return entry.first == name; });
    if (!known) into.emplace_back(name, types);
  };
  for (const auto* list : {&function.provided, &function.required}) {
    for (const SignalInterface& i : *list) {
      add(i.data_types(false));
      add(i.data_types(true));
    }
  }
}

}  // namespace smcbip::taste2bip
