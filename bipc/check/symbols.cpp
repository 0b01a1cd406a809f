// Name lookup across packages: a package sees its own declarations first, then those of the
// packages it uses, transitively; `pkg.sub.Name` looks in the package named `pkg.sub` only.
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include "bipc/check/detail/check_context.h"

namespace smcbip::bipc::detail {

struct Symbols::Impl {
  std::unordered_map<const ast::Package*, std::vector<const ast::Package*>> visible;
  std::unordered_map<const void*, const ast::Package*> owner;
};

namespace {

/// The packages `from` can name, itself first, then breadth-first along `use`.
std::vector<const ast::Package*> visible_from(const ast::Package* from) {
  std::vector<const ast::Package*> order;
  std::unordered_set<const ast::Package*> seen;
  std::deque<const ast::Package*> queue{from};
  while (!queue.empty()) {
    const ast::Package* package = queue.front();
    queue.pop_front();
    if (package == nullptr || !seen.insert(package).second) continue;
    order.push_back(package);
    for (const ast::Package* used : package->used_packages) queue.push_back(used);
  }
  return order;
}

template <typename Decl>
const Decl* find_in(const std::vector<Decl>& decls, const std::string& name) {
  for (const Decl& decl : decls) {
    if (decl.name.text == name) return &decl;
  }
  return nullptr;
}

std::string package_part(const ast::QualifiedName& name) {
  std::string joined;
  for (std::size_t i = 0; i + 1 < name.parts.size(); ++i) {
    if (!joined.empty()) joined += '.';
    joined += name.parts[i].text;
  }
  return joined;
}

/// Looks a (possibly qualified) name up among the visible packages, `member` selecting the
/// declarations of one kind.
template <typename Decl, typename Member>
const Decl* lookup(const std::vector<const ast::Package*>& visible, const ast::QualifiedName& name,
                   Member member) {
  if (name.parts.empty()) return nullptr;
  const std::string& last = name.parts.back().text;
  if (name.parts.size() == 1) {
    for (const ast::Package* package : visible) {
      if (const Decl* found = find_in(package->*member, last)) return found;
    }
    return nullptr;
  }
  const std::string qualifier = package_part(name);
  for (const ast::Package* package : visible) {
    if (package->name.text() == qualifier) return find_in(package->*member, last);
  }
  return nullptr;
}

template <typename Decl>
void register_owner(std::unordered_map<const void*, const ast::Package*>& owner,
                    const std::vector<Decl>& decls, const ast::Package* package) {
  for (const Decl& decl : decls) owner.emplace(&decl, package);
}

}  // namespace

Symbols::Symbols(const LoadedModel& model) : impl_(std::make_shared<Impl>()) {
  for (const auto& package : model.packages) {
    if (!package) continue;
    // Packages reached only through `use` are covered as well, so lookups never miss them.
    for (const ast::Package* reachable : visible_from(package.get())) {
      if (impl_->visible.count(reachable) != 0) continue;
      impl_->visible.emplace(reachable, visible_from(reachable));
      register_owner(impl_->owner, reachable->port_types, reachable);
      register_owner(impl_->owner, reachable->atom_types, reachable);
      register_owner(impl_->owner, reachable->connector_types, reachable);
      register_owner(impl_->owner, reachable->compound_types, reachable);
      register_owner(impl_->owner, reachable->extern_types, reachable);
      register_owner(impl_->owner, reachable->consts, reachable);
      register_owner(impl_->owner, reachable->extern_functions, reachable);
    }
  }
}

namespace {
const std::vector<const ast::Package*>& visible_list(
    const std::unordered_map<const ast::Package*, std::vector<const ast::Package*>>& cache,
    const ast::Package& from, std::vector<const ast::Package*>& scratch) {
  auto found = cache.find(&from);
  if (found != cache.end()) return found->second;
  scratch = visible_from(&from);  // a package outside the model (unit tests): computed each time
  return scratch;
}
}  // namespace

const ast::PortTypeDecl* Symbols::port_type(const ast::Package& from,
                                            const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::PortTypeDecl>(visible_list(impl_->visible, from, scratch), name,
                                   &ast::Package::port_types);
}

const ast::AtomTypeDecl* Symbols::atom_type(const ast::Package& from,
                                            const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::AtomTypeDecl>(visible_list(impl_->visible, from, scratch), name,
                                   &ast::Package::atom_types);
}

const ast::CompoundTypeDecl* Symbols::compound_type(const ast::Package& from,
                                                    const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::CompoundTypeDecl>(visible_list(impl_->visible, from, scratch), name,
                                       &ast::Package::compound_types);
}

const ast::ConnectorTypeDecl* Symbols::connector_type(const ast::Package& from,
                                                      const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::ConnectorTypeDecl>(visible_list(impl_->visible, from, scratch), name,
                                        &ast::Package::connector_types);
}

const ast::ExternTypeDecl* Symbols::extern_type(const ast::Package& from,
                                                const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::ExternTypeDecl>(visible_list(impl_->visible, from, scratch), name,
                                     &ast::Package::extern_types);
}

const ast::ConstDataDecl* Symbols::constant(const ast::Package& from,
                                            const ast::QualifiedName& name) const {
  std::vector<const ast::Package*> scratch;
  return lookup<ast::ConstDataDecl>(visible_list(impl_->visible, from, scratch), name,
                                    &ast::Package::consts);
}

std::vector<const ast::ExternFunctionDecl*> Symbols::functions(const ast::Package& from,
                                                               const std::string& name) const {
  std::vector<const ast::Package*> scratch;
  std::vector<const ast::ExternFunctionDecl*> found;
  for (const ast::Package* package : visible_list(impl_->visible, from, scratch)) {
    for (const ast::ExternFunctionDecl& decl : package->extern_functions) {
      if (decl.name.text == name) found.push_back(&decl);
    }
  }
  return found;
}

const ast::Package* Symbols::package_of(const void* type_decl) const {
  auto found = impl_->owner.find(type_decl);
  return found == impl_->owner.end() ? nullptr : found->second;
}

}  // namespace smcbip::bipc::detail
