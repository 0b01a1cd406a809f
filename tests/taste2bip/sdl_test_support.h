// Helpers of the SDL reader tests: reading inline text and showing expressions compactly.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "taste2bip/sdl/sdl_reader.h"

namespace smcbip::taste2bip::sdl::testing {

/// Reads `text` as file 0 and expects no diagnostics.
inline SdlFile read_ok(const std::string& text) {
  bipc::Diagnostics diags;
  SdlFile file = read_sdl(text, 0, diags);
  bipc::SourceFiles sources;
  sources.add("test.pr");
  EXPECT_TRUE(diags.all().empty()) << diags.format(sources);
  return file;
}

/// The diagnostics of reading `text` as `test.pr`, one `line:col: error: message` per line.
inline std::string read_errors(const std::string& text) {
  bipc::Diagnostics diags;
  read_sdl(text, 0, diags);
  bipc::SourceFiles sources;
  sources.add("test.pr");
  return diags.format(sources);
}

/// Every diagnostic lies within `text` (its end included): line and column from 1, the line at
/// most the text's line count, the column at most one past its size.
inline void expect_located_within(const bipc::Diagnostics& diags, const std::string& text) {
  std::size_t lines = 1;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  for (const bipc::Diagnostic& d : diags.all()) {
    EXPECT_TRUE(d.location.line >= 1 && d.location.column >= 1 && d.location.line <= lines &&
                d.location.column <= text.size() + 1)
        << d.location.line << ":" << d.location.column << ": " << d.message;
  }
}

/// An expression as a prefix form: `(+ a (* b 2))`, `(call f x)`, `{a 1, 2}`, `'s'`.
inline std::string show(const Expr& e) {
  auto list = [&](std::string head, std::size_t from) {
    for (std::size_t i = from; i < e.operands.size(); ++i) head += " " + show(e.operands[i]);
    return "(" + head + ")";
  };
  switch (e.kind) {
    case Expr::Kind::Integer:
    case Expr::Kind::Real:
    case Expr::Kind::Boolean:
    case Expr::Kind::Name:
      return e.text;
    case Expr::Kind::String:
      return "'" + e.text + "'";
    case Expr::Kind::BitString:
      return "'" + e.text + "'B";
    case Expr::Kind::OctetString:
      return "'" + e.text + "'H";
    case Expr::Kind::Field:
      return show(e.operands[0]) + "." + e.text;
    case Expr::Kind::Call:
      return list("call", 0);
    case Expr::Kind::ProcedureCall:
      return list("pcall", 0);
    case Expr::Kind::Unary:
    case Expr::Kind::Binary:
      return list(spelling(e.op), 0);
    case Expr::Kind::Conditional:
      return list("if", 0);
    case Expr::Kind::Choice:
      return e.text + ":" + show(e.operands[0]);
    case Expr::Kind::Sequence: {
      std::string out = "{";
      for (std::size_t i = 0; i < e.operands.size(); ++i) {
        if (i > 0) out += ", ";
        if (!e.field_names[i].empty()) out += e.field_names[i] + " ";
        out += show(e.operands[i]);
      }
      return out + "}";
    }
  }
  return "?";
}

/// A process with one state `S` whose input `go` runs `actions` (an SDL transition).
inline std::string in_transition(const std::string& actions) {
  return "process p;\n  state S;\n    input go;\n" + actions + "\n  endstate;\nendprocess p;\n";
}

/// The actions of the transition built by in_transition.
inline const std::vector<Action>& transition_of(const SdlFile& file) {
  static const std::vector<Action> kNone;
  if (file.processes.empty() || file.processes[0].body.states.empty() ||
      file.processes[0].body.states[0].inputs.empty()) {
    ADD_FAILURE() << "no transition read";
    return kNone;
  }
  return file.processes[0].body.states[0].inputs[0].transition.actions;
}

}  // namespace smcbip::taste2bip::sdl::testing
