#include "taste2bip/writer/wrappers.h"

#include <sstream>

namespace smcbip::taste2bip {

namespace {

std::string parameter_list(const std::vector<BipParameter>& parameters, bool typed,
                           const std::string& prefix = "") {
  std::string out;
  for (const BipParameter& p : parameters) {
    if (!out.empty()) out += ", ";
    out += (typed ? p.type + " " : "") + prefix + p.name;
  }
  return out;
}

/// Slot `slot` of the FIFO of parameter `p`: `q_<name>_<slot>`.
std::string slot_name(const BipParameter& p, std::uint32_t slot) {
  return "q_" + p.name + "_" + std::to_string(slot);
}

/// Statements that run `body(slot)` for the slot whose number is the value of `index`: BIP has
/// no arrays, so the FIFO's slots are separate data chosen by a chain of ifs.
template <typename Body>
std::string for_slot(const std::string& index, std::uint32_t size, Body body) {
  if (size == 1) return body(0);
  std::string out;
  for (std::uint32_t slot = 0; slot < size; ++slot) {
    const bool last = slot + 1 == size;
    if (slot > 0) out += " else ";
    out +=
        last ? body(slot) : "if (" + index + " == " + std::to_string(slot) + ") then " + body(slot);
  }
  for (std::uint32_t slot = 0; slot + 1 < size; ++slot) out += " fi";
  return out;
}

std::string wcet_parameters(Wcet wcet) {
  return wcet == Wcet::Zero ? "" : ", int wcet_low, int wcet_high";
}

/// The declaration of the `done` port: drawn uniformly on [wcet_low, wcet_high] after the start
/// (clock t) with Wcet::Uniform.
std::string done_port(const std::string& port_type_name, Wcet wcet) {
  std::string out;
  if (wcet == Wcet::Uniform) {
    out += "    @stochastic(dist=\"uniform\", clk=t, param=\"wcet_low,wcet_high\")\n";
  }
  return out + "    export port " + port_type_name + " done()\n";
}

/// `done` from running to `to`: at once, or within the WCET bounds (an invariant keeps it
/// before wcet_high).
std::string done_transition(const std::string& to, Wcet wcet) {
  switch (wcet) {
    case Wcet::Zero:
      return "    on done from running to " + to + " eager\n";
    case Wcet::Interval:
      return "    on done from running to " + to + " provided (t >= wcet_low) delayable\n";
    case Wcet::Uniform:
      break;
  }
  return "    on done from running to " + to + " provided (t >= wcet_low)\n";
}

/// With Wcet::Interval, `done` comes by wcet_high (invariants follow the transitions).
std::string wcet_invariant(Wcet wcet) {
  return wcet == Wcet::Interval ? "    invariant wcet_kept at running provided (t <= wcet_high)\n"
                                : "";
}

}  // namespace

std::string wrapper_type_name(const std::string& base, Wcet wcet) {
  return wcet == Wcet::Zero ? base : base + "_Wcet";
}

std::string port_type(const std::string& name, const std::vector<BipParameter>& parameters) {
  return "  port type " + name + "(" + parameter_list(parameters, true) + ")\n";
}

std::string cyclic_wrapper(const std::string& call_port, Wcet wcet) {
  std::ostringstream out;
  out << "  // A cyclic interface: started at `offset`, then every `period` after its previous\n"
         "  // start, and done within `deadline` of each start (times in milliseconds).\n"
         "  atom type "
      << wrapper_type_name("TASTE_Cyclic", wcet) << "(int period, int deadline, int offset"
      << wcet_parameters(wcet)
      << ")\n"
         "    clock t unit millisecond\n"
         "    export port "
      << call_port << " start()\n"
      << done_port(call_port, wcet)
      << "    place waiting, running, resting\n"
         "    initial to waiting do { t = 0; }\n"
         "    on start from waiting to running provided (t >= offset) eager do { t = 0; }\n"
      << done_transition("resting", wcet)
      << "    on start from resting to running provided (t >= period) eager do { t = 0; }\n"
         // The starts are eager, not bounded by invariants: a function busy with another of
         // its interfaces takes the call late, as TASTE's thread waits for the function's lock.
         "    invariant deadline_met at running provided (t <= deadline)\n"
      << wcet_invariant(wcet) << "  end\n";
  return out.str();
}

std::string sporadic_wrapper(const std::string& name, const std::string& call_port,
                             const std::string& done_port_type,
                             const std::vector<BipParameter>& parameters, std::uint32_t queue_size,
                             Wcet wcet) {
  const std::uint32_t n = queue_size;
  std::ostringstream out;
  out << "  // A sporadic interface with a FIFO of " << n
      << " calls: a call to a full FIFO is counted in `dropped`;\n"
         "  // the oldest call starts once `miat` has passed since the previous start, and is\n"
         "  // done within `deadline` of its start (times in milliseconds).\n"
         "  atom type "
      << name << "(int miat, int deadline" << wcet_parameters(wcet)
      << ")\n    clock t unit millisecond\n";
  out << "    data int count = 0\n    data int head = 0\n    data int dropped = 0\n";
  for (const BipParameter& p : parameters) {
    out << "    data " << p.type << " in_" << p.name << "\n";    // the caller's call
    out << "    data " << p.type << " next_" << p.name << "\n";  // the oldest call queued
    for (std::uint32_t slot = 0; slot < n; ++slot) {
      out << "    data " << p.type << " " << slot_name(p, slot) << "\n";
    }
  }
  out << "    export port " << call_port << " call(" << parameter_list(parameters, false, "in_")
      << ")\n";
  out << "    export port " << call_port << " start(" << parameter_list(parameters, false, "next_")
      << ")\n";
  out << done_port(done_port_type, wcet);
  out << "    port " << done_port_type << " rest()\n";
  out << "    place idle, running, resting\n";
  out << "    initial to idle do { t = 0; }\n";

  // Enqueue at (head + count) % n; the first call queued is also the next one to start.
  std::string enqueue = "if (count < " + std::to_string(n) + ") then ";
  if (!parameters.empty()) {
    enqueue += for_slot("(head + count) % " + std::to_string(n), n, [&](std::uint32_t slot) {
      std::string s;
      for (const BipParameter& p : parameters) s += slot_name(p, slot) + " = in_" + p.name + "; ";
      return s;
    });
    enqueue += " if (count == 0) then ";
    for (const BipParameter& p : parameters) enqueue += "next_" + p.name + " = in_" + p.name + "; ";
    enqueue += "fi ";
  }
  enqueue += "count = count + 1; else dropped = dropped + 1; fi";
  for (const char* place : {"idle", "running", "resting"}) {
    out << "    on call from " << place << " to " << place << " eager do { " << enqueue << " }\n";
  }

  // Dequeue: the next call becomes the one after it, if any.
  std::string dequeue = "t = 0; head = (head + 1) % " + std::to_string(n) + "; count = count - 1;";
  if (!parameters.empty()) {
    dequeue += " if (count > 0) then ";
    dequeue += for_slot("head", n, [&](std::uint32_t slot) {
      std::string s;
      for (const BipParameter& p : parameters) {
        s += "next_" + p.name + " = " + slot_name(p, slot) + "; ";
      }
      return s;
    });
    dequeue += " fi";
  }
  out << "    on start from idle to running provided (count > 0) eager do { " << dequeue << " }\n";
  out << done_transition("resting", wcet);
  out << "    on rest from resting to idle provided (t >= miat) eager\n";
  out << "    invariant deadline_met at running provided (t <= deadline)\n";
  out << wcet_invariant(wcet) << "  end\n";
  return out.str();
}

}  // namespace smcbip::taste2bip

namespace smcbip::taste2bip {

std::string synchronous_wrapper(const std::string& call_port, Wcet wcet) {
  std::ostringstream out;
  out << "  // The execution time of a protected or unprotected interface, in its caller's "
         "thread.\n"
         "  atom type "
      << wrapper_type_name("TASTE_Synchronous", wcet) << "("
      << (wcet == Wcet::Zero ? "" : "int wcet_low, int wcet_high")
      << ")\n"
         "    clock t unit millisecond\n"
         "    export port "
      << call_port << " start()\n"
      << done_port(call_port, wcet)
      << "    place idle, running\n"
         "    initial to idle\n"
         "    on start from idle to running eager do { t = 0; }\n"
      << done_transition("idle", wcet) << wcet_invariant(wcet) << "  end\n";
  return out.str();
}

}  // namespace smcbip::taste2bip
