// The recursive-descent parser of the AADL subset TASTE writes for interface views: packages,
// component types and implementations, their features, subcomponents, connections and property
// associations (values kept as tokens).
#include <set>

#include "taste2bip/interface_view/detail/aadl_syntax.h"

namespace smcbip::taste2bip::detail {
namespace {

using Kind = AadlTokenKind;

/// Brackets deeper than this in a property value are an error (the values TASTE writes are flat).
constexpr int kMaxValueNesting = 32;

const std::set<std::string, std::less<>> kCategories = {
    "abstract",  "bus",        "data",   "device", "memory",  "process",
    "processor", "subprogram", "system", "thread", "virtual", "group"};

const std::set<std::string, std::less<>> kSections = {"features",   "subcomponents", "connections",
                                                      "properties", "flows",         "modes",
                                                      "calls",      "prototypes",    "end"};

class Parser {
 public:
  Parser(const std::vector<AadlToken>& tokens, AadlErrors& errors)
      : tokens_(tokens), errors_(errors) {}

  AadlFile run() {
    AadlFile file;
    while (!at_end() && !errors_.exhausted()) {
      if (!is_word("package")) {
        expected("'PACKAGE'");
        // Resynchronise on the next package.
        while (!at_end() && !is_word("package")) ++pos_;
        continue;
      }
      file.packages.push_back(package());
    }
    return file;
  }

 private:
  const AadlToken& token() const { return tokens_[pos_]; }
  bool at_end() const { return token().kind == Kind::EndOfFile; }
  bool is(Kind kind) const { return token().kind == kind; }
  bool is_word(std::string_view word) const {
    return is(Kind::Identifier) && aadl_key(token().text) == word;
  }
  const AadlToken& take() {
    const AadlToken& t = tokens_[pos_];
    if (!at_end()) ++pos_;
    return t;
  }

  static std::string describe(const AadlToken& t) {
    switch (t.kind) {
      case Kind::EndOfFile:
        return "end of file";
      case Kind::String:
        return "string \"" + t.text + "\"";
      default:
        return "'" + t.text + "'";
    }
  }

  /// Reports `what` expected at the current token; returns false for the callers' convenience.
  bool expected(const std::string& what) {
    errors_.error(token().at, "expected " + what + ", got " + describe(token()));
    return false;
  }

  bool expect(Kind kind, const char* what) {
    if (is(kind)) {
      take();
      return true;
    }
    return expected(what);
  }

  bool expect_word(std::string_view word, const char* what) {
    if (is_word(word)) {
      take();
      return true;
    }
    return expected(what);
  }

  /// Skips to just after the next ';' outside braces (or to `end`/end of file), after an error.
  void recover() {
    int depth = 0;
    while (!at_end()) {
      if (is(Kind::LeftBrace)) ++depth;
      if (is(Kind::RightBrace) && depth > 0) --depth;
      if (depth == 0 && is(Kind::Semicolon)) {
        take();
        return;
      }
      if (depth == 0 && is_word("end")) return;
      ++pos_;
    }
  }

  /// `a::b::c` with an optional `.impl`; empty text (and an error) when no identifier is here.
  bool reference(AadlReference& ref, bool allow_impl) {
    ref.at = token().at;
    if (!is(Kind::Identifier)) return expected("a name");
    ref.text = take().text;
    while (is(Kind::DoubleColon)) {
      take();
      if (!is(Kind::Identifier)) return expected("a name after '::'");
      ref.text += "::" + take().text;
    }
    if (allow_impl && is(Kind::Dot)) {
      take();
      if (!is(Kind::Identifier)) return expected("an implementation name after '.'");
      ref.text += "." + take().text;
    }
    ref.key = aadl_key(ref.text);
    return true;
  }

  AadlPackage package() {
    AadlPackage result;
    take();  // PACKAGE
    if (!reference(result.name, false)) {
      recover();
      return result;
    }
    if (is_word("public") || is_word("private")) take();
    while (!errors_.exhausted()) {
      if (at_end()) {
        expected("'END " + result.name.text + ";'");
        return result;
      }
      if (is_word("end")) {
        take();
        AadlReference closing;
        if (reference(closing, false) && closing.key != result.name.key)
          errors_.error(closing.at,
                        "expected 'END " + result.name.text + ";', got 'END " + closing.text + "'");
        if (closing.key.empty() || !expect(Kind::Semicolon, "';'")) recover();
        return result;
      }
      if (is_word("with")) {
        take();
        AadlReference imported;
        bool ok = reference(imported, false);
        while (ok && is(Kind::Comma)) {
          take();
          ok = reference(imported, false);
        }
        if (!ok || !expect(Kind::Semicolon, "';'")) recover();
      } else if (is_word("public") || is_word("private")) {
        take();
      } else if (is_word("properties")) {
        take();
        property_list(result.properties);
      } else if (is(Kind::Identifier) && kCategories.count(aadl_key(token().text)) > 0) {
        result.classifiers.push_back(classifier());
      } else {
        expected("'WITH', a component declaration, 'PROPERTIES' or 'END'");
        ++pos_;
        recover();
      }
    }
    return result;
  }

  AadlClassifier classifier() {
    AadlClassifier result;
    result.category = aadl_key(take().text);
    if (result.category == "subprogram" && is_word("group"))
      result.category += " " + aadl_key(take().text);
    if (result.category == "virtual" && is(Kind::Identifier))
      result.category += " " + aadl_key(take().text);
    if (is_word("implementation")) {
      take();
      result.implementation = true;
    }
    if (!is(Kind::Identifier)) {
      expected("a component name");
      recover();
      return result;
    }
    result.name = take();
    if (result.implementation) {
      if (!is(Kind::Dot)) {
        expected("'.' and the implementation name");
        recover();
        return result;
      }
      take();
      if (!is(Kind::Identifier)) {
        expected("an implementation name");
        recover();
        return result;
      }
      result.name.text += "." + take().text;
    }
    if (is_word("extends")) {
      take();
      AadlReference base;
      if (!reference(base, true)) {
        recover();
        return result;
      }
    }
    while (!errors_.exhausted()) {
      if (at_end()) {
        expected("'END " + result.name.text + ";'");
        return result;
      }
      if (is_word("features")) {
        take();
        member_list(result.features, false);
      } else if (is_word("subcomponents")) {
        take();
        member_list(result.subcomponents, false);
      } else if (is_word("connections")) {
        take();
        member_list(result.connections, true);
      } else if (is_word("properties")) {
        take();
        property_list(result.properties);
      } else if (is_word("end")) {
        take();
        AadlReference closing;
        if (reference(closing, true) && closing.key != aadl_key(result.name.text))
          errors_.error(closing.at,
                        "expected 'END " + result.name.text + ";', got 'END " + closing.text + "'");
        if (closing.key.empty() || !expect(Kind::Semicolon, "';'")) recover();
        return result;
      } else {
        expected("'FEATURES', 'SUBCOMPONENTS', 'CONNECTIONS', 'PROPERTIES' or 'END'");
        ++pos_;
        recover();
      }
    }
    return result;
  }

  bool at_section() const {
    return is(Kind::Identifier) && kSections.count(aadl_key(token().text)) > 0;
  }

  /// Members up to the next section keyword: `name : words [reference] [{props}];`, a connection
  /// with `end -> end` after its words; `none;` is an empty list.
  void member_list(std::vector<AadlMember>& members, bool connections) {
    if (is_word("none")) {
      take();
      if (!expect(Kind::Semicolon, "';'")) recover();
      return;
    }
    while (!at_end() && !at_section() && !errors_.exhausted()) {
      AadlMember member;
      if (!is(Kind::Identifier)) {
        expected(connections ? "a connection name" : "a feature or subcomponent name");
        recover();
        continue;
      }
      member.name = take();
      if (!expect(Kind::Colon, "':'")) {
        recover();
        continue;
      }
      if (!member_body(member, connections)) {
        recover();
        continue;
      }
      members.push_back(std::move(member));
    }
  }

  static bool is_category_word(const std::string& key) {
    static const std::set<std::string, std::less<>> kWords = {
        "in",     "out",    "parameter", "provides", "requires", "subprogram", "access", "data",
        "event",  "port",   "feature",   "group",    "bus",      "system",     "thread", "process",
        "device", "memory", "processor", "abstract", "virtual",  "refined",    "to"};
    return kWords.count(key) > 0;
  }

  bool member_body(AadlMember& member, bool connection) {
    // The category words; the classifier reference starts at the first name that is not one.
    while (is(Kind::Identifier) && is_category_word(aadl_key(token().text))) {
      if (!member.words.empty()) member.words += ' ';
      member.words += aadl_key(take().text);
    }
    if (member.words.empty())
      return expected(connection ? "a connection kind ('SUBPROGRAM ACCESS')"
                                 : "a feature or component category");
    if (connection) {
      if (!reference(member.source, true)) return false;
      if (!is(Kind::Connect) && !is(Kind::BiConnect)) return expected("'->'");
      take();
      if (!reference(member.destination, true)) return false;
    } else if (is(Kind::Identifier)) {
      if (!reference(member.classifier, true)) return false;
    }
    if (is(Kind::LeftBrace)) {
      take();
      while (!is(Kind::RightBrace) && !errors_.exhausted()) {
        if (at_end()) return expected("'}'");
        if (!property(member.properties)) return false;
      }
      take();
    }
    return expect(Kind::Semicolon, "';'");
  }

  void property_list(std::vector<AadlProperty>& properties) {
    if (is_word("none")) {
      take();
      if (!expect(Kind::Semicolon, "';'")) recover();
      return;
    }
    while (!at_end() && !at_section() && !errors_.exhausted()) {
      if (!property(properties)) recover();
    }
  }

  /// `Name => value;`; the value's tokens are kept whatever their syntax (brackets balanced).
  bool property(std::vector<AadlProperty>& properties) {
    AadlProperty result;
    AadlReference name;
    if (!is(Kind::Identifier)) return expected("a property name");
    if (!reference(name, false)) return false;
    result.name = name.text;
    result.key = name.key;
    result.at = name.at;
    if (!is(Kind::Associate) && !is(Kind::AddAssociate)) return expected("'=>'");
    take();
    result.value_at = token().at;
    std::vector<Kind> open;
    while (true) {
      if (at_end()) return expected("';' after the value of " + result.name);
      if (open.empty() && is(Kind::Semicolon)) break;
      // `end` is reserved: a value never holds it, so a missing ';' is reported where it was due.
      if (is_word("end")) return expected("';' after the value of " + result.name);
      if (is(Kind::LeftParen) || is(Kind::LeftBracket)) {
        if (open.size() >= kMaxValueNesting)
          return expected("at most " + std::to_string(kMaxValueNesting) +
                          " nested brackets in a property value");
        open.push_back(is(Kind::LeftParen) ? Kind::RightParen : Kind::RightBracket);
      } else if (is(Kind::RightParen) || is(Kind::RightBracket)) {
        if (open.empty() || open.back() != token().kind)
          return expected(open.empty()
                              ? std::string("';'")
                              : std::string(open.back() == Kind::RightParen ? "')'" : "']'"));
        open.pop_back();
      } else if (is(Kind::LeftBrace) || is(Kind::RightBrace)) {
        return expected(open.empty()
                            ? "';' after the value of " + result.name
                            : std::string(open.back() == Kind::RightParen ? "')'" : "']'"));
      }
      result.value.push_back(take());
    }
    take();  // ;
    if (result.value.empty()) {
      errors_.error(result.value_at, "expected a value for " + result.name + ", got ';'");
      return true;
    }
    properties.push_back(std::move(result));
    return true;
  }

  const std::vector<AadlToken>& tokens_;
  AadlErrors& errors_;
  std::size_t pos_ = 0;
};

}  // namespace

AadlFile parse_aadl(const std::vector<AadlToken>& tokens, AadlErrors& errors) {
  return Parser(tokens, errors).run();
}

}  // namespace smcbip::taste2bip::detail
