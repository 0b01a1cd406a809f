// The whole front end in one call: load, check, pick and check the root, instantiate.
#include "bipc/bipc.h"

#include "bipc/parse/lexer.h"

namespace smcbip::bipc {

namespace {
Location file_start(std::uint32_t file) { return Location{file, 1, 1}; }
}  // namespace

bool is_keyword(std::string_view word) {
  return detail::keyword_kind(word) != detail::TokenKind::Identifier;
}

FrontendResult run_frontend(const FrontendOptions& options, bool need_system) {
  FrontendResult result;
  result.model = load(options.file, options.include_dirs, result.diags);
  if (result.diags.has_errors() || result.model.main == nullptr) return result;
  if (!check(result.model, result.diags)) return result;

  std::string root_text = options.root;
  // The command line is a source of its own for positions in the root text.
  const std::uint32_t root_file = result.model.files.add("<--root>");
  if (root_text.empty()) {
    if (!need_system) return result;
    std::optional<std::string> chosen = default_root(result.model);
    if (!chosen) {
      result.diags.error(file_start(0),
                         "no root given and no single top-level compound type to choose: "
                         "pass --root 'Type()'");
      return result;
    }
    root_text = *chosen;
  }
  std::optional<ast::ComponentDecl> root = parse_root(root_text, root_file, result.diags);
  if (!root || result.diags.has_errors()) return result;
  if (!check_root(result.model, *root, result.diags)) return result;
  result.system = instantiate(result.model, *root, result.diags);
  if (result.diags.has_errors()) result.system.reset();
  return result;
}

}  // namespace smcbip::bipc
