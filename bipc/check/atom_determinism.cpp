// Non-determinism an atom's text shows: two transitions on one port (or two internal ones) whose
// source places are nested, so both are enabled whenever the one with more places is. Unguarded
// pairs are errors and guarded ones warnings, after the Verimag front end's
// checkDuplicatedTriggerPortFromSameState; its coverability analysis of disjoint sources is left
// to the engines, which report the non-determinism when it happens (exit code 1).
#include <algorithm>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

/// Whether the transition's port and places all resolved (errors are reported elsewhere).
bool resolved(const ast::Transition& t) {
  if (t.port && t.port_index < 0) return false;
  return std::none_of(t.from_index.begin(), t.from_index.end(), [](int p) { return p < 0; });
}

bool contains_all(const std::vector<int>& big, const std::vector<int>& small) {
  return std::all_of(small.begin(), small.end(),
                     [&big](int p) { return std::find(big.begin(), big.end(), p) != big.end(); });
}

/// Whether both transitions are enabled whenever their guards hold in the larger one's places.
bool overlap(const ast::Transition& a, const ast::Transition& b) {
  if (a.port_index != b.port_index || !resolved(a) || !resolved(b)) return false;
  return contains_all(a.from_index, b.from_index) || contains_all(b.from_index, a.from_index);
}

bool suppressed(const ast::Annotations& annotations) {
  return suppresses(annotations, "nondeterminism");
}

std::string places_text(const ast::Transition& t) {
  std::string text;
  for (const ast::Ident& place : t.from) text += (text.empty() ? "" : ", ") + place.text;
  return text;
}

std::string subject(const ast::Transition& t) {
  return t.port ? "transitions on port '" + t.port->text + "'" : "internal transitions";
}

void report(const ast::Transition& later, const ast::Transition& earlier, bool guarded,
            Diagnostics& diags) {
  const std::string pair = subject(later) + " from " + places_text(later) + " (here) and from " +
                           places_text(earlier) + " (line " + std::to_string(earlier.loc.line) +
                           ")";
  if (guarded) {
    diags.warning(later.loc, "possible non-determinism: " + pair +
                                 " can be enabled together when both guards hold; "
                                 "@SuppressWarning(nondeterminism) accepts it");
  } else {
    diags.error(later.loc,
                "non-determinism: " + pair + " can be enabled together, and neither has a guard");
  }
  diags.note(earlier.loc, "the other transition is here");
}

}  // namespace

void check_atom_determinism(const ast::AtomTypeDecl& atom, const ast::Package& package,
                            Diagnostics& diags) {
  const bool warnings_off = suppressed(atom.annotations) || suppressed(package.annotations);
  const std::vector<ast::Transition>& all = atom.transitions;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const ast::Transition* warned_with = nullptr;
    bool failed = false;
    for (std::size_t j = 0; j < i && !failed; ++j) {
      if (!overlap(all[i], all[j])) continue;
      if (!all[i].guard && !all[j].guard) {
        report(all[i], all[j], false, diags);
        failed = true;
      } else if (warned_with == nullptr && !(all[i].guard && all[j].guard &&
                                             guards_exclusive(*all[i].guard, *all[j].guard))) {
        warned_with = &all[j];
      }
    }
    // One diagnostic per transition (an error rather than a warning), as the Verimag front end
    // reports them.
    if (!failed && warned_with != nullptr && !warnings_off && !suppressed(all[i].annotations)) {
      report(all[i], *warned_with, true, diags);
    }
  }
}

}  // namespace smcbip::bipc::detail
