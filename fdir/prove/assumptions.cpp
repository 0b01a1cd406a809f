// Parsing assumption files with Z3 and checking their inductiveness, one net transition at a
// time (the consecution check of an inductive invariant, relative to the invariants known).
#include "fdir/prove/assumptions.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "fdir/invariants/trap_invariants.h"
#include "fdir/prove/deadlock_predicate.h"

namespace smcbip::fdir {

namespace {

using bipc::ir::ValueKind;

/// Traps added against one pre-state of the check (as many as the prover adds per candidate).
constexpr std::size_t kTrapsPerState = 4096;

bool tracked(const z3::expr& e) { return e.is_int() || e.is_bool(); }

/// A top-level command of an SMT-LIB2 text: its name and the position of its `(`.
struct Command {
  std::string name;
  unsigned line = 0, column = 0;
};

/// The top-level commands of an SMT-LIB2 text, and the text with its comments blanked out
/// (Z3 4.8's scanner counts the columns of a line after a comment one too far).
struct Scan {
  std::vector<Command> commands;
  std::string text;
};

/// Scans `text`, skipping comments, strings and quoted symbols (what is malformed beyond that
/// is left to Z3's parser, which reports it).
Scan scan(const std::string& text) {
  Scan out{{}, text};
  unsigned line = 1, column = 1;
  int depth = 0;
  for (std::size_t k = 0; k < text.size(); ++k, ++column) {
    const char ch = text[k];
    if (ch == '\n') {
      ++line;
      column = 0;
    } else if (ch == ';') {
      for (; k < text.size() && text[k] != '\n'; ++k) out.text[k] = ' ';
      --k;
    } else if (ch == '"' || ch == '|') {
      for (++k, ++column; k < text.size() && text[k] != ch; ++k, ++column) {
        if (text[k] == '\n') {
          ++line;
          column = 0;
        }
      }
    } else if (ch == '(') {
      if (depth++ == 0) {
        std::size_t end = k + 1;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) ||
                                     text[end] == '-' || text[end] == '_')) {
          ++end;
        }
        out.commands.push_back({text.substr(k + 1, end - k - 1), line, column});
      }
    } else if (ch == ')') {
      --depth;
    }
  }
  return out;
}

/// The declarations the parser sees, and the place constants to replace by the state's own.
struct Names {
  explicit Names(z3::context& c) : sorts(c), decls(c), plain_places(c), place_vars(c) {}
  z3::sort_vector sorts;
  z3::func_decl_vector decls;
  z3::expr_vector plain_places, place_vars;
  std::map<std::string, std::string> untracked;  // datum name -> its type, not followed
};

Names declared_names(const StateEncoding& state) {
  z3::context& c = state.context();
  Names names(c);
  std::set<std::string> data;
  for (Index a = 0; a < state.system().atoms.size(); ++a) {
    const auto& type = state.system().atom_types[state.system().atoms[a].type];
    for (std::size_t k = 0; k < state.data(a).size(); ++k) {
      const z3::expr& d = state.data(a)[k];
      const std::string name = d.decl().name().str();
      data.insert(name);
      if (tracked(d)) {
        names.decls.push_back(d.decl());
      } else {
        names.untracked[name] = bipc::ir::value_kind_name(type.data[k].type.kind);
      }
    }
  }
  for (Index p = 0; p < state.net().places.size(); ++p) {
    const z3::expr& var = state.place(p);
    names.decls.push_back(var.decl());  // `@ROOT.atom.place`
    const std::string& plain = state.net().places[p];
    if (data.contains(plain)) continue;
    const z3::expr alias = c.bool_const(plain.c_str());
    names.decls.push_back(alias.decl());
    names.plain_places.push_back(alias);
    names.place_vars.push_back(var);
  }
  return names;
}

/// Z3's parse error as a located one. The text is given to Z3 after a newline, so that every
/// line is scanned alike: Z3 then gives lines one too far and columns from 0.
[[noreturn]] void parse_error(const std::string& file, const std::string& message,
                              const Names& names) {
  static const std::regex located(R"re(\(error "line (\d+) column (\d+): ([^"]*)"\))re");
  std::smatch m;
  if (!std::regex_search(message, m, located)) throw AssumptionError(file, 0, 0, message);
  const unsigned line = static_cast<unsigned>(std::stoul(m[1].str())) - 1;
  const unsigned column = static_cast<unsigned>(std::stoul(m[2].str())) + 1;
  std::string what = m[3].str();
  static const std::regex unknown("unknown constant (\\S+)");
  std::smatch u;
  if (std::regex_search(what, u, unknown)) {
    const auto found = names.untracked.find(u[1].str());
    what =
        found != names.untracked.end()
            ? u[1].str() + " is a " + found->second +
                  " datum: assumptions range over places and int and bool data"
            : "unknown name " + u[1].str() + " (places are ROOT.atom.place, data ROOT.atom.datum)";
  }
  throw AssumptionError(file, line, column, what);
}

}  // namespace

std::vector<Assumption> parse_assumptions(const AssumptionSource& source,
                                          const StateEncoding& state) {
  static const std::set<std::string> allowed{"assert", "define-fun", "define-sort", "set-info",
                                             "check-sat"};
  const Scan scanned = scan(source.text);
  for (const Command& command : scanned.commands) {
    if (!allowed.contains(command.name)) {
      throw AssumptionError(source.file, command.line, command.column,
                            "'" + command.name +
                                "' is not allowed in an assumption file (only assert, "
                                "define-fun, define-sort, set-info, check-sat): assumptions "
                                "speak of the model's names only");
    }
  }
  Names names = declared_names(state);
  z3::expr_vector parsed(state.context());
  try {
    parsed = state.context().parse_string(("\n" + scanned.text).c_str(), names.sorts, names.decls);
  } catch (const z3::exception& e) {
    parse_error(source.file, e.msg(), names);
  }
  std::vector<Command> asserts;
  for (const Command& command : scanned.commands) {
    if (command.name == "assert") asserts.push_back(command);
  }
  std::vector<Assumption> out;
  for (unsigned k = 0; k < parsed.size(); ++k) {
    const Command at = k < asserts.size() ? asserts[k] : Command{};
    z3::expr_vector from = names.plain_places, to = names.place_vars;
    out.push_back({{source.file, at.line, at.column, parsed[static_cast<int>(k)].to_string()},
                   parsed[static_cast<int>(k)].substitute(from, to)});
  }
  return out;
}

namespace {

/// The effect of one net transition: when it is enabled, and the values of the places and data
/// it changes (`from` replaced by `to`), with the bounds its unknown values keep.
struct Effect {
  explicit Effect(z3::context& c)
      : enabled(c.bool_val(true)), bounds(c.bool_val(true)), from(c), to(c) {}
  z3::expr enabled, bounds;
  z3::expr_vector from, to;
};

/// Adds the new values of `atom`'s followed data to `effect`, with their 64-bit bounds.
void add_data(const StateEncoding& state, Index atom, const std::vector<z3::expr>& values,
              Effect& effect) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    const z3::expr& before = state.data(atom)[k];
    if (!tracked(before)) continue;
    effect.from.push_back(before);
    effect.to.push_back(values[k]);
    effect.bounds = effect.bounds && int64_bounds(values[k]);
  }
}

Effect transition_effect(const StateEncoding& state, CodeEncoder& encoder, const NetTransition& t) {
  const bipc::ir::System& system = state.system();
  const NetInteraction& interaction = state.net().interactions[t.interaction];
  Effect effect(state.context());
  encoder.clear_fresh();
  effect.enabled = interaction_enabled(state, encoder, t.interaction);
  for (Index p : t.pre) effect.enabled = effect.enabled && state.place(p);
  for (Index p : t.pre) {
    if (std::binary_search(t.post.begin(), t.post.end(), p)) continue;  // taken and put back
    effect.from.push_back(state.place(p));
    effect.to.push_back(state.context().bool_val(false));
  }
  for (Index p : t.post) {
    effect.from.push_back(state.place(p));
    effect.to.push_back(state.context().bool_val(true));
  }
  const bipc::ir::Code* down = nullptr;
  if (interaction.code >= 0) {
    const auto& type = system.connector_types[system.connectors[interaction.connector].type];
    down = &type.interactions[static_cast<std::size_t>(interaction.code)].down;
  }
  std::map<Index, std::vector<z3::expr>> after;  // per atom taking part: its data afterwards
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    const AtomMove& move = t.moves[i];
    const auto& type = system.atom_types[system.atoms[move.atom].type];
    const bipc::ir::Transition& tr = type.transitions[move.transition];
    CodeFrame guard{state.data(move.atom), &system.atoms[move.atom].params, {}};
    effect.enabled = effect.enabled && encoder.expression(tr.guard, guard);
    CodeFrame frame{after.try_emplace(move.atom, state.data(move.atom)).first->second,
                    &system.atoms[move.atom].params,
                    {}};
    // Data transfer is not followed: what the connector writes through the port may be anything.
    if (down && tr.port != bipc::ir::kNone && writes_port(*down, interaction.ports[i][0].param)) {
      for (Index slot : type.ports[tr.port].data) {
        frame.data[slot] = encoder.unknown(type.data[slot].type.kind);
      }
    }
    encoder.statement(tr.action, frame);
    after[move.atom] = frame.data;
  }
  for (const auto& [atom, values] : after) add_data(state, atom, values, effect);
  for (const z3::expr& u : encoder.fresh()) effect.bounds = effect.bounds && int64_bounds(u);
  return effect;
}

/// The initial state: the initially marked places, and the data after their initial values
/// and the initial action (unknown values free), as the component invariants start from.
Effect initial_effect(const StateEncoding& state, CodeEncoder& encoder) {
  z3::context& c = state.context();
  const bipc::ir::System& system = state.system();
  Effect effect(c);
  encoder.clear_fresh();
  for (Index p = 0; p < state.net().places.size(); ++p) {
    effect.from.push_back(state.place(p));
    effect.to.push_back(c.bool_val(state.net().initial[p] != 0));
  }
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const auto& type = system.atom_types[system.atoms[a].type];
    CodeFrame frame;
    frame.params = &system.atoms[a].params;
    for (const bipc::ir::Data& d : type.data) {
      const ValueKind kind = d.type.kind;
      frame.data.push_back(kind == ValueKind::Bool  ? c.bool_val(false)
                           : kind == ValueKind::Int ? c.int_val(0)
                                                    : encoder.unknown(kind));
    }
    for (std::size_t k = 0; k < type.data.size(); ++k) {
      if (!type.data[k].initial_value.empty()) {
        frame.data[k] = encoder.expression(type.data[k].initial_value, frame);
      }
    }
    encoder.statement(type.initial_action, frame);
    add_data(state, a, frame.data, effect);
  }
  for (const z3::expr& u : encoder.fresh()) effect.bounds = effect.bounds && int64_bounds(u);
  return effect;
}

/// `ROOT.t: p.put (full -> idle), c.get (ready -> busy)`.
std::string transition_name(const StateEncoding& state, const NetTransition& t) {
  const bipc::ir::System& system = state.system();
  std::string out = state.net().interactions[t.interaction].name + ":";
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    const AtomMove& m = t.moves[i];
    const auto& type = system.atom_types[system.atoms[m.atom].type];
    const bipc::ir::Transition& tr = type.transitions[m.transition];
    out += std::string(i ? ", " : " ") + system.atoms[m.atom].path + "." +
           (tr.port == bipc::ir::kNone ? std::string("internal") : type.ports[tr.port].name) + " (";
    for (std::size_t k = 0; k < tr.from.size(); ++k) {
      out += (k ? " " : "") + type.places[tr.from[k]];
    }
    out += " ->";
    for (Index p : tr.to) out += " " + type.places[p];
    out += ")";
  }
  return out;
}

void collect_constants(const z3::expr& e, std::set<unsigned>& seen, std::vector<z3::expr>& out) {
  if (!seen.insert(e.id()).second) return;
  if (e.is_const() && e.decl().decl_kind() == Z3_OP_UNINTERPRETED) {
    out.push_back(e);
    return;
  }
  if (e.is_quantifier()) {
    collect_constants(e.body(), seen, out);
    return;
  }
  if (!e.is_app()) return;
  for (unsigned k = 0; k < e.num_args(); ++k) collect_constants(e.arg(k), seen, out);
}

/// The values, in `model`, of the state variables `formula` reads, before and after `effect`
/// (places by their plain name): `ROOT.c.y = 1 -> 2`.
std::string values_text(const z3::model& model, const z3::expr& formula, const Effect& effect,
                        bool with_after) {
  std::vector<z3::expr> vars;
  std::set<unsigned> seen;
  collect_constants(formula, seen, vars);
  std::string out;
  for (const z3::expr& v : vars) {
    std::string name = v.decl().name().str();
    if (!name.empty() && name[0] == '@') name.erase(0, 1);
    z3::expr_vector from = effect.from, to = effect.to;
    const z3::expr next = z3::expr(v).substitute(from, to);
    out += (out.empty() ? "" : ", ") + name + " = ";
    if (with_after) out += model.eval(v, true).to_string() + " -> ";
    out += model.eval(next, true).to_string();
  }
  return out;
}

/// The first assumption false in `model` after `effect`.
const Assumption& first_broken(const std::vector<Assumption>& assumptions, const z3::model& model,
                               const Effect& effect) {
  for (const Assumption& a : assumptions) {
    z3::expr_vector from = effect.from, to = effect.to;
    if (model.eval(z3::expr(a.formula).substitute(from, to), true).is_false()) return a;
  }
  return assumptions.front();
}

void check_initial(const std::vector<Assumption>& assumptions, const StateEncoding& state,
                   CodeEncoder& encoder) {
  const Effect init = initial_effect(state, encoder);
  for (const Assumption& a : assumptions) {
    z3::solver solver(state.context());
    z3::expr_vector from = init.from, to = init.to;
    solver.add(init.bounds && !z3::expr(a.formula).substitute(from, to));
    const z3::check_result r = solver.check();
    if (r == z3::unsat) continue;
    if (r == z3::unknown) {
      throw AssumptionError(a.site.file, a.site.line, a.site.column,
                            "Z3 cannot decide whether this assumption holds initially (" +
                                solver.reason_unknown() + "): it is not used");
    }
    throw AssumptionError(a.site.file, a.site.line, a.site.column,
                          "this assumption does not hold in the initial state (" +
                              values_text(solver.get_model(), a.formula, init, false) + ")");
  }
}

}  // namespace

void check_inductive(const std::vector<Assumption>& assumptions, const StateEncoding& state,
                     CodeEncoder& encoder, z3::expr_vector& invariant, std::size_t& traps) {
  if (assumptions.empty()) return;
  check_initial(assumptions, state, encoder);
  z3::context& c = state.context();
  z3::solver solver(c);
  for (const z3::expr& clause : invariant) solver.add(clause);
  for (const Assumption& a : assumptions) solver.add(a.formula);
  for (const NetTransition& t : state.net().transitions) {
    const Effect effect = transition_effect(state, encoder, t);
    z3::expr_vector after(c);
    for (const Assumption& a : assumptions) {
      z3::expr_vector from = effect.from, to = effect.to;
      after.push_back(z3::expr(a.formula).substitute(from, to));
    }
    for (;;) {
      solver.push();
      solver.add(effect.enabled && effect.bounds && !z3::mk_and(after));
      const z3::check_result r = solver.check();
      if (r == z3::unsat) {
        solver.pop();
        break;
      }
      const Assumption& first = assumptions.front();
      if (r == z3::unknown) {
        throw AssumptionError(first.site.file, first.site.line, first.site.column,
                              "Z3 cannot decide whether net transition " +
                                  transition_name(state, t) + " keeps the assumptions (" +
                                  solver.reason_unknown() + "): they are not used");
      }
      const z3::model model = solver.get_model();
      solver.pop();
      std::vector<std::uint8_t> marking(state.net().places.size());
      for (Index p = 0; p < marking.size(); ++p) {
        marking[p] = model.eval(state.place(p), true).is_true() ? 1 : 0;
      }
      const std::vector<std::vector<Index>> found =
          excluding_traps(state.net(), marking, kTrapsPerState);
      if (found.empty()) {
        const Assumption& broken = first_broken(assumptions, model, effect);
        throw AssumptionError(
            broken.site.file, broken.site.line, broken.site.column,
            "this assumption is not inductive: net transition " + transition_name(state, t) +
                " leads from a state where the invariants and the assumptions hold to one "
                "where it does not (" +
                values_text(model, broken.formula, effect, true) + ")");
      }
      for (const std::vector<Index>& trap : found) {
        z3::expr_vector places(c);
        for (Index p : trap) places.push_back(state.place(p));
        const z3::expr clause = z3::mk_or(places);
        solver.add(clause);
        invariant.push_back(clause);
        ++traps;
      }
    }
  }
}

}  // namespace smcbip::fdir
