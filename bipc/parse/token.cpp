// Token spellings, keyword lookup, token descriptions and the per-file error budget.
#include <array>
#include <unordered_map>
#include <utility>

#include "bipc/parse/lexer.h"

namespace smcbip::bipc::detail {

namespace {

struct Spelling {
  TokenKind kind;
  std::string_view text;
};

constexpr std::array kKeywords = {
    Spelling{TokenKind::KwInt, "int"},
    Spelling{TokenKind::KwBool, "bool"},
    Spelling{TokenKind::KwFloat, "float"},
    Spelling{TokenKind::KwString, "string"},
    Spelling{TokenKind::KwTrue, "true"},
    Spelling{TokenKind::KwFalse, "false"},
    Spelling{TokenKind::KwPackage, "package"},
    Spelling{TokenKind::KwUse, "use"},
    Spelling{TokenKind::KwEnd, "end"},
    Spelling{TokenKind::KwConst, "const"},
    Spelling{TokenKind::KwData, "data"},
    Spelling{TokenKind::KwExtern, "extern"},
    Spelling{TokenKind::KwType, "type"},
    Spelling{TokenKind::KwRefine, "refine"},
    Spelling{TokenKind::KwAs, "as"},
    Spelling{TokenKind::KwFunction, "function"},
    Spelling{TokenKind::KwOperator, "operator"},
    Spelling{TokenKind::KwPort, "port"},
    Spelling{TokenKind::KwAtom, "atom"},
    Spelling{TokenKind::KwCompound, "compound"},
    Spelling{TokenKind::KwConnector, "connector"},
    Spelling{TokenKind::KwComponent, "component"},
    Spelling{TokenKind::KwExport, "export"},
    Spelling{TokenKind::KwRemember, "remember"},
    Spelling{TokenKind::KwIgnore, "ignore"},
    Spelling{TokenKind::KwError, "error"},
    Spelling{TokenKind::KwClock, "clock"},
    Spelling{TokenKind::KwUnit, "unit"},
    Spelling{TokenKind::KwNanosecond, "nanosecond"},
    Spelling{TokenKind::KwMicrosecond, "microsecond"},
    Spelling{TokenKind::KwMillisecond, "millisecond"},
    Spelling{TokenKind::KwSecond, "second"},
    Spelling{TokenKind::KwMinute, "minute"},
    Spelling{TokenKind::KwHour, "hour"},
    Spelling{TokenKind::KwDay, "day"},
    Spelling{TokenKind::KwPlace, "place"},
    Spelling{TokenKind::KwInitial, "initial"},
    Spelling{TokenKind::KwOn, "on"},
    Spelling{TokenKind::KwInternal, "internal"},
    Spelling{TokenKind::KwFrom, "from"},
    Spelling{TokenKind::KwTo, "to"},
    Spelling{TokenKind::KwAt, "at"},
    Spelling{TokenKind::KwProvided, "provided"},
    Spelling{TokenKind::KwDo, "do"},
    Spelling{TokenKind::KwResume, "resume"},
    Spelling{TokenKind::KwLazy, "lazy"},
    Spelling{TokenKind::KwDelayable, "delayable"},
    Spelling{TokenKind::KwEager, "eager"},
    Spelling{TokenKind::KwPriority, "priority"},
    Spelling{TokenKind::KwInvariant, "invariant"},
    Spelling{TokenKind::KwDefine, "define"},
    Spelling{TokenKind::KwUp, "up"},
    Spelling{TokenKind::KwDown, "down"},
    Spelling{TokenKind::KwSync, "sync"},
    Spelling{TokenKind::KwAsync, "async"},
    Spelling{TokenKind::KwIf, "if"},
    Spelling{TokenKind::KwThen, "then"},
    Spelling{TokenKind::KwElse, "else"},
    Spelling{TokenKind::KwFi, "fi"},
};

constexpr std::array kSymbols = {
    Spelling{TokenKind::LParen, "("}, Spelling{TokenKind::RParen, ")"},
    Spelling{TokenKind::LBrace, "{"}, Spelling{TokenKind::RBrace, "}"},
    Spelling{TokenKind::Comma, ","},  Spelling{TokenKind::Quote, "'"},
    Spelling{TokenKind::Dot, "."},    Spelling{TokenKind::Semicolon, ";"},
    Spelling{TokenKind::Colon, ":"},  Spelling{TokenKind::AtSign, "@"},
    Spelling{TokenKind::Assign, "="}, Spelling{TokenKind::Lt, "<"},
    Spelling{TokenKind::Gt, ">"},     Spelling{TokenKind::Le, "<="},
    Spelling{TokenKind::Ge, ">="},    Spelling{TokenKind::EqEq, "=="},
    Spelling{TokenKind::NotEq, "!="}, Spelling{TokenKind::AndAnd, "&&"},
    Spelling{TokenKind::OrOr, "||"},  Spelling{TokenKind::Not, "!"},
    Spelling{TokenKind::Tilde, "~"},  Spelling{TokenKind::Plus, "+"},
    Spelling{TokenKind::Minus, "-"},  Spelling{TokenKind::Star, "*"},
    Spelling{TokenKind::Slash, "/"},  Spelling{TokenKind::Percent, "%"},
    Spelling{TokenKind::Amp, "&"},    Spelling{TokenKind::Pipe, "|"},
    Spelling{TokenKind::Caret, "^"},
};

}  // namespace

void ErrorBudget::error(Location at, std::string message) {
  if (exhausted()) return;
  diags_.error(at, std::move(message));
  ++count_;
  if (exhausted()) {
    diags_.note(at,
                concat({"too many errors (", std::to_string(max_), "); giving up on this file"}));
  }
}

TokenKind keyword_kind(std::string_view word) {
  static const std::unordered_map<std::string_view, TokenKind> table = [] {
    std::unordered_map<std::string_view, TokenKind> keywords;
    for (const Spelling& keyword : kKeywords) keywords.emplace(keyword.text, keyword.kind);
    return keywords;
  }();
  auto found = table.find(word);
  return found == table.end() ? TokenKind::Identifier : found->second;
}

bool is_soft_keyword(TokenKind kind) {
  switch (kind) {
    case TokenKind::KwUp:
    case TokenKind::KwDown:
    case TokenKind::KwSync:
    case TokenKind::KwAsync:
    case TokenKind::KwNanosecond:
    case TokenKind::KwMicrosecond:
    case TokenKind::KwMillisecond:
    case TokenKind::KwSecond:
    case TokenKind::KwMinute:
    case TokenKind::KwHour:
    case TokenKind::KwDay:
    case TokenKind::KwUnit:
    case TokenKind::KwLazy:
    case TokenKind::KwDelayable:
    case TokenKind::KwEager:
    case TokenKind::KwRemember:
    case TokenKind::KwIgnore:
    case TokenKind::KwError:
    case TokenKind::KwRefine:
    case TokenKind::KwFunction:
    case TokenKind::KwOperator:
    case TokenKind::KwAt:
    case TokenKind::KwAs:
      return true;
    default:
      return false;
  }
}

std::string_view spelling(TokenKind kind) {
  for (const Spelling& keyword : kKeywords) {
    if (keyword.kind == kind) return keyword.text;
  }
  for (const Spelling& symbol : kSymbols) {
    if (symbol.kind == kind) return symbol.text;
  }
  return {};
}

std::string concat(std::initializer_list<std::string_view> parts) {
  std::string joined;
  for (std::string_view part : parts) joined += part;
  return joined;
}

std::string describe(const Token& token) {
  constexpr std::size_t kMaxShown = 24;
  switch (token.kind) {
    case TokenKind::EndOfFile:
      return "end of file";
    case TokenKind::Invalid:
      return "an invalid token";
    case TokenKind::String: {
      std::string shown(token.text.substr(0, kMaxShown));
      if (token.text.size() > kMaxShown) shown += "...";
      return "string " + shown;
    }
    default: {
      std::string shown(token.text.substr(0, kMaxShown));
      if (token.text.size() > kMaxShown) shown += "...";
      return "'" + shown + "'";
    }
  }
}

}  // namespace smcbip::bipc::detail
