// The ASN.1 reader's recursive-descent parser, split by grammar area over parser*.cpp;
// internal to the data view reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/asn1/lexer.h"

namespace smcbip::taste2bip::asn1::detail {

/// Errors per file after which reading stops.
constexpr std::size_t kMaxErrors = 20;
/// Nesting of types after which reading stops (the parser recurses once per level).
constexpr int kMaxDepth = 200;

inline bool starts_upper(std::string_view s) { return !s.empty() && s[0] >= 'A' && s[0] <= 'Z'; }

/// How a token is named in messages: `'text'` or `the end of the file`.
std::string describe(const Token& t);

/// Reads the modules of one file into a DataView; each parse function reports its error and
/// returns false, and the assignment loop recovers at the next assignment.
class Parser {
 public:
  Parser(const std::string& text, std::uint32_t file, DataView& into, bipc::Diagnostics& diags)
      : text_(text), into_(into), diags_(diags), first_error_(diags.error_count()) {
    tokens_ = tokenize(text, file, diags, kMaxErrors);
    eof_ = tokens_.back();
    if (errors() >= kMaxErrors) stop();
  }

  void run() {
    while (cur().kind != TokenKind::EndOfFile) parse_module();
  }

 private:
  // --- tokens and errors -------------------------------------------------------------------
  std::size_t errors() const { return diags_.error_count() - first_error_; }
  const Token& cur() const { return stopped_ ? eof_ : tokens_[pos_]; }
  const Token& next(std::size_t ahead = 1) const {
    if (stopped_) return eof_;
    return pos_ + ahead < tokens_.size() ? tokens_[pos_ + ahead] : tokens_.back();
  }
  void advance() {
    if (!stopped_ && pos_ + 1 < tokens_.size()) ++pos_;
  }
  bool accept(std::string_view text) {
    if (!cur().is(text)) return false;
    advance();
    return true;
  }
  void stop() {
    if (!stopped_) diags_.note(cur().at, "too many errors: the rest of the file is not read");
    stopped_ = true;
  }
  /// Reports an error; always returns false so that parse functions can `return error(...)`.
  bool error(bipc::Location at, std::string message) {
    if (stopped_) return false;
    diags_.error(at, std::move(message));
    if (errors() >= kMaxErrors) stop();
    return false;
  }
  bool expect(std::string_view text, const std::string& what) {
    if (accept(text)) return true;
    return error(cur().at,
                 "expected '" + std::string(text) + "' " + what + ", got " + describe(cur()));
  }
  std::string_view source_between(std::size_t from, std::size_t to) const {
    return std::string_view(text_).substr(from, to - from);
  }
  std::size_t end_of_previous() const {
    const Token& t = tokens_[pos_ == 0 ? 0 : pos_ - 1];
    return t.offset + t.text.size();
  }

  // --- modules --------------------------------------------------------------------------------
  void skip_to_end();
  void parse_module();
  void parse_exports(Module& m);
  void parse_imports(Module& m);
  void skip_imports();
  bool skip_braces();

  // --- assignments ----------------------------------------------------------------------------
  void recover();
  void parse_assignment(Module& m);
  bool parse_parameters(TypeAssignment& a);

  // --- types ----------------------------------------------------------------------------------
  bool parse_type(Type& t, int depth);
  bool parse_builtin(Type& t, int depth);
  bool parse_arguments(Type& t);
  bool parse_enumerants(Type& t);
  bool parse_components(Type& t, int depth);
  // --- constraints ----------------------------------------------------------------------------
  bool parse_constraint(Type& t);
  bool parse_size(Type& t);
  bool parse_ranges(Constraint& c);
  bool parse_bound(Value& v, const std::string& where);

  // --- values ---------------------------------------------------------------------------------
  bool parse_value_text(std::string& out);

  const std::string& text_;
  DataView& into_;
  bipc::Diagnostics& diags_;
  std::size_t first_error_;
  std::vector<Token> tokens_;
  Token eof_;
  std::size_t pos_ = 0;
  bool stopped_ = false;
};

}  // namespace smcbip::taste2bip::asn1::detail
