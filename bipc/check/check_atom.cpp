// Atom types: declarations (parameters, data, ports, clocks, places), the Petri net's initial
// transition and transitions, and invariants; priorities and @stochastic have their own files.
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Where = ExprContext::Where;

/// Parameters, data, ports (with merged export names) and clocks share one namespace.
void declare_names(const ast::AtomTypeDecl& atom, Diagnostics& diags) {
  std::vector<const ast::Ident*> names;
  for (const ast::ParamDecl& param : atom.params) names.push_back(&param.name);
  for (const ast::DataDecl& data : atom.data) names.push_back(&data.name);
  std::vector<Location> merged_seen;
  for (const ast::PortDecl& port : atom.ports) {
    names.push_back(&port.name);
    if (!port.merged_as) continue;
    const Location at = port.merged_as->loc;
    bool seen = false;  // the ports of one declaration share the same `as` name
    for (const Location& other : merged_seen) {
      seen = seen || (other.file == at.file && other.line == at.line && other.column == at.column);
    }
    if (!seen) {
      merged_seen.push_back(at);
      names.push_back(&*port.merged_as);
    }
  }
  for (const ast::ClockDecl& clock : atom.clocks) names.push_back(&clock.name);
  declare_in_source_order(names, diags);
  NameScope places(diags);
  for (const ast::Ident& place : atom.places) places.declare(place);
}

void check_params(ast::AtomTypeDecl& atom, const ast::Package& package, const Symbols& symbols,
                  Diagnostics& diags) {
  for (ast::ParamDecl& param : atom.params) {
    resolve_type(param.type, package, symbols, diags);
    require_native_type(param.type, "parameter '" + param.name.text + "'", diags);
  }
}

/// What kind of constant `name` denotes in the atom ("data", "parameter"), or "" for none:
/// constant data of the atom, its parameters and the package constants.
std::string constant_kind(const std::string& name, const ast::AtomTypeDecl& atom,
                          const ast::Package& package, const Symbols& symbols) {
  if (const int d = index_of(atom.data, name); d >= 0) {
    return atom.data[d].type.is_const ? "data" : "";
  }
  if (index_of(atom.params, name) >= 0) return "parameter";
  if (symbols.constant(package, ast::QualifiedName{{ast::Ident{name, {}}}}) != nullptr) {
    return "data";
  }
  return "";
}

/// One bound name of a port: it must be variable data of the atom, of exactly the parameter's
/// type.
int bind_data(const ast::PortDecl& port, const ast::Ident& bound, std::size_t k,
              const ast::AtomTypeDecl& atom, const ast::Package& package, const Symbols& symbols,
              Diagnostics& diags) {
  if (const std::string kind = constant_kind(bound.text, atom, package, symbols); !kind.empty()) {
    report_bound_constant(bound, kind, "a port", diags);
    return -1;
  }
  const int d = index_of(atom.data, bound.text);
  if (d >= 0) {
    check_bound_type("port", port.name, port.port_type, k, bound, atom.data[d].type.resolved,
                     diags);
  } else if (index_of(atom.clocks, bound.text) >= 0) {
    diags.error(bound.loc, "port '" + port.name.text + "' cannot bind clock '" + bound.text +
                               "': only data can be bound");
  } else {
    diags.error(bound.loc,
                "undeclared data '" + bound.text + "' bound by port '" + port.name.text + "'");
  }
  return d;
}

void check_port(ast::PortDecl& port, const ast::AtomTypeDecl& atom, const ast::Package& package,
                const Symbols& symbols, Diagnostics& diags) {
  port.port_type = resolve_port_type(port.type, package, symbols, diags);
  check_bound_count("port", port.name, port.type, port.port_type, port.bound_data.size(), diags);
  port.bound_data_index.clear();
  for (std::size_t k = 0; k < port.bound_data.size(); ++k) {
    port.bound_data_index.push_back(
        bind_data(port, port.bound_data[k], k, atom, package, symbols, diags));
  }
  check_stochastic(port, atom, diags);
}

/// Resolves a list of places, each at most once.
std::vector<int> resolve_places(const std::vector<ast::Ident>& names, const ast::AtomTypeDecl& atom,
                                const char* list, Diagnostics& diags) {
  std::vector<int> indices;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int p = index_of_ident(atom.places, names[i].text);
    if (p < 0 && !names[i].text.empty()) {
      diags.error(names[i].loc, "undeclared place '" + names[i].text + "'");
    }
    if (index_of_ident({names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i)},
                       names[i].text) >= 0) {
      diags.error(names[i].loc,
                  "place '" + names[i].text + "' appears twice in '" + std::string(list) + "'");
    }
    indices.push_back(p);
  }
  return indices;
}

void check_resume(std::optional<ast::ResumeClause>& resume, ExprContext ctx, const Symbols& symbols,
                  Diagnostics& diags) {
  if (!resume || !resume->guard) return;
  ctx.where = Where::Resume;
  check_condition(*resume->guard, ctx, symbols, diags, "a resume condition");
}

void check_initial(ast::AtomTypeDecl& atom, ExprContext ctx, const Symbols& symbols,
                   Diagnostics& diags) {
  resolve_places(atom.initial.to, atom, "to", diags);
  ctx.where = Where::AtomInit;
  check_block(atom.initial.action, ctx, symbols, diags);
  check_resume(atom.initial.resume, ctx, symbols, diags);
}

/// Internal transitions are not synchronised, so they carry no timing: no clock, no urgency.
void check_internal(const ast::Transition& t, Diagnostics& diags) {
  if (const ast::Expr* clock = t.guard ? first_clock(*t.guard) : nullptr) {
    diags.error(clock->loc, "the guard of an internal transition cannot use clock '" +
                                clock->name.text() + "': only transitions on ports are timed");
  }
  if (t.urgency) {
    diags.error(t.loc, "an internal transition cannot have an urgency (eager, delayable, lazy)");
  }
}

void check_transition(ast::Transition& t, ast::AtomTypeDecl& atom, ExprContext ctx,
                      const Symbols& symbols, Diagnostics& diags) {
  t.port_index = -1;
  if (t.port) {
    t.port_index = index_of(atom.ports, t.port->text);
    if (t.port_index < 0 && !t.port->text.empty()) {
      diags.error(t.port->loc, "undeclared port '" + t.port->text + "'");
    }
  }
  t.from_index = resolve_places(t.from, atom, "from", diags);
  t.to_index = resolve_places(t.to, atom, "to", diags);
  if (t.guard) {
    ctx.where = Where::AtomGuard;
    check_condition(*t.guard, ctx, symbols, diags, "a transition guard");
  }
  if (!t.port) check_internal(t, diags);
  ctx.where = Where::AtomAction;
  check_block(t.action, ctx, symbols, diags);
  check_resume(t.resume, ctx, symbols, diags);
}

void check_invariant(ast::InvariantDecl& invariant, const ast::AtomTypeDecl& atom, ExprContext ctx,
                     const Symbols& symbols, Diagnostics& diags) {
  invariant.place_index =
      resolve_places(invariant.places, atom, invariant.at ? "at" : "from", diags);
  if (!invariant.guard) return;
  ctx.where = Where::Invariant;
  check_condition(*invariant.guard, ctx, symbols, diags, "an invariant");
}

}  // namespace

void check_atom_type(ast::AtomTypeDecl& type, const ast::Package& package, const Symbols& symbols,
                     Diagnostics& diags) {
  declare_names(type, diags);
  check_params(type, package, symbols, diags);
  ExprContext ctx;
  ctx.where = Where::AtomInit;
  ctx.package = &package;
  ctx.atom = &type;
  check_data_declarations(type.data, ctx, symbols, diags);
  for (ast::PortDecl& port : type.ports) check_port(port, type, package, symbols, diags);
  check_initial(type, ctx, symbols, diags);
  for (ast::Transition& t : type.transitions) check_transition(t, type, ctx, symbols, diags);
  check_atom_determinism(type, package, diags);
  check_atom_priorities(type, ctx, symbols, diags);
  for (ast::InvariantDecl& invariant : type.invariants) {
    check_invariant(invariant, type, ctx, symbols, diags);
  }
}

}  // namespace smcbip::bipc::detail
