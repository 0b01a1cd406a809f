// Where a lexer of taste2bip stands in its text: the byte it reads and that byte's line and
// column, so that every token and error is located the same way in every input language.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::detail {

/// The lexers derive from it: `text_[pos_]` is the byte under the cursor.
class TextCursor {
 protected:
  TextCursor(std::string_view text, std::uint32_t file) : text_(text), file_(file) {}

  /// The byte `ahead` bytes on, or '\0' past the end.
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  /// Moves one byte on (not past the end); a newline starts the next line. Columns count bytes.
  void advance() {
    if (pos_ >= text_.size()) return;
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }
  /// The location of the byte under the cursor.
  bipc::Location here() const { return {file_, line_, column_}; }

  std::string_view text_;
  std::size_t pos_ = 0;

 private:
  std::uint32_t file_;
  std::uint32_t line_ = 1, column_ = 1;
};

}  // namespace smcbip::taste2bip::detail
