// Annotations the checker reads itself: one given twice on a declaration (`@doc @doc port type
// P()`), which the Verimag front end refuses since later stages read one value per name, and
// `@SuppressWarning(name, ...)`, which silences the named warnings on its element.
#include <set>
#include <tuple>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using LocationKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;

class RedefinitionCheck {
 public:
  explicit RedefinitionCheck(Diagnostics& diags) : diags_(diags) {}

  /// Reports every annotation of `annotations` whose name an earlier one already has.
  void check(const ast::Annotations& annotations, const std::string& what) {
    for (std::size_t i = 0; i < annotations.size(); ++i) {
      const ast::Annotation& later = annotations[i];
      for (std::size_t j = 0; j < i; ++j) {
        if (annotations[j].name.text != later.name.text) continue;
        report(later, annotations[j], what);
        break;
      }
    }
  }

  template <typename Decl>
  void check_each(const std::vector<Decl>& decls, const std::string& kind) {
    for (const Decl& decl : decls) check(decl.annotations, kind + " '" + decl.name.text + "'");
  }

 private:
  void report(const ast::Annotation& later, const ast::Annotation& first, const std::string& what) {
    // `port T p(), q()` gives both ports the same annotations: report them once.
    if (!reported_.insert({later.loc.file, later.loc.line, later.loc.column}).second) return;
    diags_.error(later.loc, "annotation '@" + later.name.text + "' is redefined on " + what +
                                ": a declaration takes each annotation once");
    diags_.note(first.loc, "it is first given here");
  }

  Diagnostics& diags_;
  std::set<LocationKey> reported_;
};

void check_atom(const ast::AtomTypeDecl& atom, RedefinitionCheck& check) {
  check.check(atom.annotations, "atom type '" + atom.name.text + "'");
  check.check_each(atom.data, "data");
  check.check_each(atom.ports, "port");
  check.check_each(atom.clocks, "clock");
  for (const ast::Transition& t : atom.transitions) {
    check.check(t.annotations, "a transition of atom type '" + atom.name.text + "'");
  }
}

void check_connector(const ast::ConnectorTypeDecl& connector, RedefinitionCheck& check) {
  check.check(connector.annotations, "connector type '" + connector.name.text + "'");
  check.check_each(connector.data, "data");
  if (connector.export_port) {
    check.check(connector.export_port->annotations,
                "exported port '" + connector.export_port->name.text + "'");
  }
  for (const ast::InteractionDecl& interaction : connector.interactions) {
    check.check(interaction.annotations,
                "an interaction of connector type '" + connector.name.text + "'");
  }
}

void check_compound(const ast::CompoundTypeDecl& compound, RedefinitionCheck& check) {
  check.check(compound.annotations, "compound type '" + compound.name.text + "'");
  check.check_each(compound.components, "component");
  check.check_each(compound.connectors, "connector");
  check.check_each(compound.port_exports, "exported port");
  check.check_each(compound.data_exports, "exported data");
}

}  // namespace

bool suppresses(const ast::Annotations& annotations, const std::string& warning) {
  for (const ast::Annotation& annotation : annotations) {
    if (annotation.name.text != "SuppressWarning") continue;
    for (const ast::AnnotationParam& param : annotation.params) {
      if (param.key.text == warning) return true;
    }
  }
  return false;
}

void check_annotation_redefinitions(const ast::Package& package, Diagnostics& diags) {
  RedefinitionCheck check(diags);
  check.check(package.annotations, "package '" + package.name.text() + "'");
  check.check_each(package.consts, "constant");
  check.check_each(package.extern_types, "extern type");
  check.check_each(package.extern_functions, "extern function");
  check.check_each(package.port_types, "port type");
  for (const ast::AtomTypeDecl& atom : package.atom_types) check_atom(atom, check);
  for (const ast::ConnectorTypeDecl& connector : package.connector_types) {
    check_connector(connector, check);
  }
  for (const ast::CompoundTypeDecl& compound : package.compound_types) {
    check_compound(compound, check);
  }
}

}  // namespace smcbip::bipc::detail
