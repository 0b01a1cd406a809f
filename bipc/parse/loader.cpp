// Loading a model: the package of the given file and the packages it uses, transitively.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "bipc/bipc.h"

namespace smcbip::bipc {

namespace {

// Packages are loaded depth-first, one stack frame level per `use`: a chain this long is refused
// before it exhausts the stack (no model we know of goes beyond a handful of levels).
constexpr std::size_t kMaxUseDepth = 256;

std::optional<std::string> read_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return text;
}

std::string join_path(const std::string& dir, const std::string& relative) {
  if (dir.empty()) return relative;
  return (std::filesystem::path(dir) / relative).string();
}

// Resolves `use` transitively, loading each package once; packages are appended to the model
// after the packages they use, so dependencies come first.
class Loader {
 public:
  Loader(LoadedModel& model, const std::vector<std::string>& search_dirs, Diagnostics& diags)
      : model_(model), search_dirs_(search_dirs), diags_(diags) {}

  ast::Package* load(const std::string& path, const ast::QualifiedName* used_as);

 private:
  std::optional<std::string> find_package(const std::string& name, const std::string& user,
                                          std::vector<std::string>& searched) const;
  void resolve_use(ast::Package& package, const ast::QualifiedName& use);

  LoadedModel& model_;
  const std::vector<std::string>& search_dirs_;
  Diagnostics& diags_;
  std::map<std::string, ast::Package*> loaded_;  // by name; null when the file was unreadable
  std::vector<std::string> loading_;             // the chain of `use` being followed
};

std::optional<std::string> Loader::find_package(const std::string& name, const std::string& user,
                                                std::vector<std::string>& searched) const {
  std::string nested = name;
  std::replace(nested.begin(), nested.end(), '.', '/');
  const std::vector<std::string> relatives = {nested + ".bip", name + ".bip"};
  std::vector<std::string> dirs = {std::filesystem::path(user).parent_path().string()};
  dirs.insert(dirs.end(), search_dirs_.begin(), search_dirs_.end());
  for (const std::string& dir : dirs) {
    for (const std::string& relative : relatives) {
      std::string candidate = join_path(dir, relative);
      if (std::find(searched.begin(), searched.end(), candidate) != searched.end()) continue;
      searched.push_back(candidate);
      std::error_code error;
      if (std::filesystem::is_regular_file(candidate, error)) return candidate;
    }
  }
  return std::nullopt;
}

void Loader::resolve_use(ast::Package& package, const ast::QualifiedName& use) {
  const std::string name = use.text();
  auto cycle_start = std::find(loading_.begin(), loading_.end(), name);
  if (cycle_start != loading_.end()) {
    std::string chain;
    for (auto it = cycle_start; it != loading_.end(); ++it) chain += *it + " -> ";
    diags_.error(use.loc(), "cyclic 'use' of package '" + name + "' (" + chain + name + ")");
    return;
  }
  auto known = loaded_.find(name);
  if (known != loaded_.end()) {
    if (known->second != nullptr) package.used_packages.push_back(known->second);
    return;
  }
  if (loading_.size() >= kMaxUseDepth) {
    diags_.error(use.loc(), "'use' of package '" + name + "' nested more than " +
                                std::to_string(kMaxUseDepth) + " levels deep; not supported");
    return;
  }
  std::vector<std::string> searched;
  std::optional<std::string> found = find_package(name, package.path, searched);
  if (!found) {
    std::string list;
    for (const std::string& candidate : searched) list += (list.empty() ? "" : ", ") + candidate;
    diags_.error(use.loc(), "cannot find package '" + name + "' (searched: " + list + ")");
    return;
  }
  if (ast::Package* used = load(*found, &use)) package.used_packages.push_back(used);
}

ast::Package* Loader::load(const std::string& path, const ast::QualifiedName* used_as) {
  const std::uint32_t file = model_.files.add(path);
  const std::optional<std::string> text = read_file(path);
  std::unique_ptr<ast::Package> package;
  if (text) {
    package = parse_package(*text, file, diags_);
    package->path = path;
  } else {
    diags_.error({file, 1, 1}, "cannot open file");
  }
  ast::Package* raw = package.get();
  std::string key = used_as != nullptr ? used_as->text() : (raw ? raw->name.text() : path);
  loaded_[key] = raw;
  if (raw == nullptr) return nullptr;

  const std::string declared = raw->name.text();
  if (used_as != nullptr && !raw->name.parts.empty() && declared != key) {
    diags_.error(raw->name.loc(), "this file declares package '" + declared +
                                      "' but was found for 'use " + key +
                                      "'; a package file must declare the package it is named "
                                      "after");
  }
  loading_.push_back(key);
  for (const ast::QualifiedName& use : raw->uses) resolve_use(*raw, use);
  loading_.pop_back();
  model_.packages.push_back(std::move(package));
  return raw;
}

}  // namespace

LoadedModel load(const std::string& path, const std::vector<std::string>& search_dirs,
                 Diagnostics& diags) {
  LoadedModel model;
  Loader loader(model, search_dirs, diags);
  model.main = loader.load(path, nullptr);
  return model;
}

}  // namespace smcbip::bipc
