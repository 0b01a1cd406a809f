// The timing wrappers of provided interfaces and the connectors of the calls, after the original
// translation: a cyclic or sporadic interface runs in its own thread (the wrapper starts it),
// a protected or unprotected one in its caller's (the call and the return are rendezvous of
// caller, callee and the wrapper that gives the execution its time).
#include <limits>

#include "taste2bip/translate/detail/package_parts.h"

namespace smcbip::taste2bip::detail {

namespace {

/// A deadline the view does not give: none (the longest time an int holds).
constexpr std::int64_t kNoDeadline = std::numeric_limits<std::int32_t>::max();

std::string qualified(const FunctionSignature& f, const SignalInterface& i) {
  return f.name + "." + i.name;
}

std::string connector(const std::string& type, const std::string& name,
                      const std::vector<std::string>& ends) {
  std::string list;
  for (const std::string& e : ends) list += (list.empty() ? "" : ", ") + e;
  return "    connector " + type + " " + name + "(" + list + ")\n";
}

std::string wcet_arguments(const Interface& i, const std::string& what, Wcet wcet,
                           PackageParts& parts) {
  if (wcet == Wcet::Zero) return "";
  const auto low = whole_milliseconds(i.wcet_low.value_or(0), what + " WCET", parts);
  const auto high = whole_milliseconds(i.wcet_high.value_or(0), what + " WCET", parts);
  return ", " + std::to_string(low) + ", " + std::to_string(high);
}

/// The execution time an interface gets: --wcet's, when the view gives its WCET; none else (the
/// bound would count the time its caller waits in synchronous calls, and 0 would stop time).
Wcet effective_wcet(const Interface& i, const std::string& what, Wcet wcet, PackageParts& parts) {
  if (wcet == Wcet::Zero || i.wcet_high) return wcet;
  parts.report.push_back(what + ": no WCET in the view: it runs in no time");
  return Wcet::Zero;
}

std::string deadline_argument(const Interface& i, const std::string& what, PackageParts& parts) {
  const double period = i.period.value_or(0);
  const double deadline = i.deadline.value_or(0) > 0 ? *i.deadline : period;
  if (deadline <= 0) {
    parts.report.push_back(what + ": no deadline in the view: none");
    return std::to_string(kNoDeadline);
  }
  if (!i.deadline || *i.deadline <= 0) {
    parts.report.push_back(what + ": no deadline in the view: its period, " +
                           std::to_string(static_cast<std::int64_t>(period)) + " ms");
  }
  return std::to_string(whole_milliseconds(deadline, what + " deadline", parts));
}

void cyclic(const FunctionSignature& f, const SignalInterface& p, Wcet wcet, PackageParts& parts,
            bipc::Diagnostics& diags) {
  const Interface& i = *p.source;
  const std::string what = qualified(f, p), instance = f.name + "_" + p.name;
  if (!p.data_types(false).empty() || !p.data_types(true).empty()) {
    diags.error(p.at, "cyclic interface " + what + " has parameters, which TASTE does not allow");
    return;
  }
  wcet = effective_wcet(i, what, wcet, parts);
  const std::string type = wrapper_type_name("TASTE_Cyclic", wcet);
  parts.atom_types.add(type, cyclic_wrapper(use_port_type({}, parts), wcet));
  const std::string args =
      std::to_string(whole_milliseconds(i.period.value_or(1000), what + " period", parts)) + ", " +
      deadline_argument(i, what, parts) + ", " +
      std::to_string(whole_milliseconds(i.dispatch_offset.value_or(0), what + " offset", parts)) +
      wcet_arguments(i, what, wcet, parts);
  parts.components.push_back("    component " + type + " " + instance + "(" + args + ")\n");
  parts.report.push_back(what + ": cyclic, wrapper " + instance + " " + type + "(" + args + ")");
  const std::string sync = use_connector_type({}, 0, parts);
  parts.connectors.push_back(
      connector(sync, instance + "_start", {instance + ".start", f.name + "." + p.name + "_in"}));
  parts.connectors.push_back(
      connector(sync, instance + "_done", {f.name + "." + p.name + "_return", instance + ".done"}));
}

void sporadic(const FunctionSignature& f, const SignalInterface& p, Wcet wcet, PackageParts& parts,
              bipc::Diagnostics& diags) {
  const Interface& i = *p.source;
  const std::string what = qualified(f, p), instance = f.name + "_" + p.name;
  if (!p.data_types(true).empty()) {
    diags.error(p.at, "sporadic interface " + what +
                          " has out parameters, which TASTE does not "
                          "allow");
    return;
  }
  const std::uint32_t size = i.queue_size.value_or(1);
  if (size < 1 || size > kMaxQueueSize) {
    diags.error(i.at, "the queue of " + what + " holds " + std::to_string(size) +
                          " calls: from 1 to " + std::to_string(kMaxQueueSize) + " are translated");
    return;
  }
  const auto types = p.data_types(false);
  const std::string port = use_port_type(types, parts);
  wcet = effective_wcet(i, what, wcet, parts);
  const std::string type =
      wrapper_type_name("TASTE_Sporadic_" + port + "_" + std::to_string(size), wcet);
  std::vector<BipParameter> parameters;
  for (std::size_t k = 0; k < types.size(); ++k)
    parameters.push_back({"a" + std::to_string(k), types[k]});
  parts.atom_types.add(
      type, sporadic_wrapper(type, port, use_port_type({}, parts), parameters, size, wcet));
  const std::string args =
      std::to_string(whole_milliseconds(i.period.value_or(0), what + " MIAT", parts)) + ", " +
      deadline_argument(i, what, parts) + wcet_arguments(i, what, wcet, parts);
  parts.components.push_back("    component " + type + " " + instance + "(" + args + ")\n");
  parts.report.push_back(what + ": sporadic, queue of " + std::to_string(size) + ", wrapper " +
                         instance + " " + type + "(" + args + ")");
  parts.connectors.push_back(connector(use_connector_type(types, 0, parts), instance + "_start",
                                       {instance + ".start", f.name + "." + p.name + "_in"}));
  parts.connectors.push_back(connector(use_connector_type({}, 0, parts), instance + "_done",
                                       {f.name + "." + p.name + "_return", instance + ".done"}));
}

void synchronous(const FunctionSignature& f, const SignalInterface& p, Wcet wcet,
                 PackageParts& parts) {
  const Interface& i = *p.source;
  const std::string what = qualified(f, p);
  wcet = effective_wcet(i, what, wcet, parts);
  const std::string type = wrapper_type_name("TASTE_Synchronous", wcet);
  parts.atom_types.add(type, synchronous_wrapper(use_port_type({}, parts), wcet));
  std::string args = wcet_arguments(i, what, wcet, parts);
  if (!args.empty()) args = args.substr(2);
  parts.components.push_back("    component " + type + " " + f.name + "_" + p.name + "(" + args +
                             ")\n");
  parts.report.push_back(what +
                         (p.kind == InterfaceKind::Protected ? ": protected" : ": unprotected") +
                         ", run in its caller's thread, wrapper " + f.name + "_" + p.name + " " +
                         type + "(" + args + ")");
  if (p.kind == InterfaceKind::Unprotected) {
    parts.report.push_back(what + ": unprotected, yet run one at a time with " + f.name +
                           "'s other interfaces (one atom per function)");
  }
}

struct Callee {
  const FunctionSignature* function = nullptr;
  const SignalInterface* provided = nullptr;
};

std::vector<std::pair<Callee, const Connection*>> callees(
    const InterfaceView& view, const std::vector<FunctionSignature>& functions,
    const FunctionSignature& caller, const SignalInterface& required) {
  std::vector<std::pair<Callee, const Connection*>> out;
  for (const Connection& c : view.connections) {
    if (c.from.function != caller.source->name || c.from.interface != required.source->name) {
      continue;
    }
    for (const FunctionSignature& g : functions) {
      if (g.source->name != c.to.function) continue;
      for (const SignalInterface& q : g.provided) {
        if (q.source->name == c.to.interface) out.push_back({Callee{&g, &q}, &c});
      }
    }
  }
  return out;
}

void call(const FunctionSignature& f, const SignalInterface& r, const Callee& callee,
          const Connection& at, PackageParts& parts, bipc::Diagnostics& diags) {
  const FunctionSignature& g = *callee.function;
  const SignalInterface& q = *callee.provided;
  const std::string name = f.name + "_" + r.name + "_to_" + g.name + "_" + q.name;
  if (r.data_types(false) != q.data_types(false) || r.data_types(true) != q.data_types(true)) {
    diags.error(at.at, qualified(f, r) + " and " + qualified(g, q) + " do not carry the same data");
    return;
  }
  const std::string wrapper = g.name + "_" + q.name;
  switch (q.kind) {
    case InterfaceKind::Sporadic:
      parts.connectors.push_back(connector(use_connector_type(r.data_types(false), 0, parts), name,
                                           {f.name + "." + r.name + "_out", wrapper + ".call"}));
      return;
    case InterfaceKind::Protected:
    case InterfaceKind::Unprotected:
      parts.connectors.push_back(connector(
          use_connector_type(r.data_types(false), 1, parts), name,
          {f.name + "." + r.name + "_out", g.name + "." + q.name + "_in", wrapper + ".start"}));
      parts.connectors.push_back(connector(use_connector_type(r.data_types(true), 1, parts),
                                           name + "_return",
                                           {g.name + "." + q.name + "_return",
                                            f.name + "." + r.name + "_result", wrapper + ".done"}));
      return;
    default:
      diags.error(at.at, qualified(f, r) + " calls " + qualified(g, q) +
                             ", which is cyclic: a cyclic interface has no callers");
  }
}

}  // namespace

void connect_function(const InterfaceView& view, const std::vector<FunctionSignature>& functions,
                      std::size_t index, Wcet wcet, PackageParts& parts, bipc::Diagnostics& diags) {
  const FunctionSignature& f = functions[index];
  for (const SignalInterface& p : f.provided) {
    if (p.kind == InterfaceKind::Cyclic) cyclic(f, p, wcet, parts, diags);
    if (p.kind == InterfaceKind::Sporadic) sporadic(f, p, wcet, parts, diags);
    if (p.synchronous()) synchronous(f, p, wcet, parts);
  }
  for (const SignalInterface& r : f.required) {
    const auto reached = callees(view, functions, f, r);
    for (const auto& [callee, at] : reached) call(f, r, callee, *at, parts, diags);
    if (reached.empty()) {
      parts.report.push_back(qualified(f, r) + ": connected to nothing: its calls go nowhere");
      parts.connectors.push_back(connector(use_lone_connector_type(r.data_types(false), parts),
                                           f.name + "_" + r.name + "_unconnected",
                                           {f.name + "." + r.name + "_out"}));
    }
  }
}

}  // namespace smcbip::taste2bip::detail
