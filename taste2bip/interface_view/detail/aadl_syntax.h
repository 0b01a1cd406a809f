// The AADL subset TASTE writes for interface views: tokens, a declaration tree, and the lexer and
// parser that build it (the interface view reader then interprets the tree).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::detail {

/// Reports errors until a per-file cap, then one last error saying the rest was given up.
class AadlErrors {
 public:
  static constexpr std::size_t kMaxErrors = 20;
  explicit AadlErrors(bipc::Diagnostics& diags) : diags_(diags) {}
  void error(bipc::Location at, std::string message);
  /// True once the cap is reached: readers stop as soon as they see it.
  bool exhausted() const { return count_ >= kMaxErrors; }
  std::size_t count() const { return count_; }

 private:
  bipc::Diagnostics& diags_;
  std::size_t count_ = 0;
};

enum class AadlTokenKind : std::uint8_t {
  EndOfFile,
  Identifier,  // keywords too: AADL keywords are reserved words compared without case
  Number,
  String,  // text without the quotes
  Colon,
  DoubleColon,
  Semicolon,
  Associate,     // =>
  AddAssociate,  // +=>
  Connect,       // ->
  BiConnect,     // <->
  LeftBrace,
  RightBrace,
  LeftParen,
  RightParen,
  LeftBracket,
  RightBracket,
  Comma,
  Dot,
  DotDot,
  Plus,
  Minus,
  Star,
};

struct AadlToken {
  AadlTokenKind kind = AadlTokenKind::EndOfFile;
  std::string text;  // as written (a string's text without its quotes)
  bipc::Location at;
};

/// The tokens of `text`, ending with EndOfFile; comments (`--` to end of line) are dropped.
std::vector<AadlToken> lex_aadl(std::string_view text, std::uint32_t file, AadlErrors& errors);

/// `name` lowercased (ASCII), the form AADL compares identifiers in.
std::string aadl_key(std::string_view name);

/// `Pkg::Sub::Name.impl` as written, and its lowercase key.
struct AadlReference {
  std::string text, key;
  bipc::Location at;
};

/// `Name => value;` with the value's tokens kept for the reader to interpret.
struct AadlProperty {
  std::string name, key;  // qualified (`Taste::RCMperiod`); key lowercase
  bipc::Location at;
  std::vector<AadlToken> value;
  bipc::Location value_at;
};

/// A feature, subcomponent or connection: `name : words reference {properties};` where words are
/// the category keywords (`in parameter`, `provides subprogram access`, `system`, ...).
struct AadlMember {
  AadlToken name;
  std::string words;         // the keywords lowercased and joined by single spaces
  AadlReference classifier;  // empty text when none
  // Connections only: the two ends, each `component.feature` or `feature`.
  AadlReference source, destination;
  std::vector<AadlProperty> properties;
};

struct AadlClassifier {
  std::string category;  // lowercase: `system`, `subprogram`, `data`, ...
  bool implementation = false;
  AadlToken name;  // `F` or `F.others`
  std::vector<AadlMember> features, subcomponents, connections;
  std::vector<AadlProperty> properties;
};

struct AadlPackage {
  AadlReference name;
  std::vector<AadlClassifier> classifiers;
  std::vector<AadlProperty> properties;
};

struct AadlFile {
  std::vector<AadlPackage> packages;
};

/// Parses `tokens` (from lex_aadl); syntax errors are located at the offending token.
AadlFile parse_aadl(const std::vector<AadlToken>& tokens, AadlErrors& errors);

}  // namespace smcbip::taste2bip::detail
