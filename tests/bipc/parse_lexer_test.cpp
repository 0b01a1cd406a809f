// Tests of the BIP2 lexer: token kinds, values, positions and lexical errors.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bipc/parse/lexer.h"

namespace smcbip::bipc::detail {
namespace {

// Tokens view their text: callers pass literals or strings that outlive the tokens.
std::vector<Token> lex(std::string_view text, Diagnostics& diags) {
  return lex_all(text, 0, diags);
}

std::vector<TokenKind> kinds(const std::vector<Token>& tokens) {
  std::vector<TokenKind> result;
  for (const Token& token : tokens) result.push_back(token.kind);
  return result;
}

std::string first_error(const Diagnostics& diags) {
  for (const Diagnostic& d : diags.all()) {
    if (d.severity == Severity::Error) {
      return std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
             d.message;
    }
  }
  return "";
}

TEST(ParseLexer, KeywordsIdentifiersAndPositions) {
  Diagnostics diags;
  std::string text = "package p\n\tatom type A_1 ()\nend";
  std::vector<Token> tokens = lex(text, diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(tokens.size(), 9u);
  EXPECT_EQ(kinds(tokens),
            (std::vector<TokenKind>{TokenKind::KwPackage, TokenKind::Identifier, TokenKind::KwAtom,
                                    TokenKind::KwType, TokenKind::Identifier, TokenKind::LParen,
                                    TokenKind::RParen, TokenKind::KwEnd, TokenKind::EndOfFile}));
  EXPECT_EQ(tokens[1].text, "p");
  EXPECT_EQ(tokens[1].loc.line, 1u);
  EXPECT_EQ(tokens[1].loc.column, 9u);
  // A tab counts as one column.
  EXPECT_EQ(tokens[2].loc.line, 2u);
  EXPECT_EQ(tokens[2].loc.column, 2u);
  EXPECT_EQ(tokens[4].text, "A_1");
  EXPECT_EQ(tokens[4].loc.column, 12u);
  EXPECT_EQ(tokens[5].loc.column, 16u);
  EXPECT_EQ(tokens[7].loc.line, 3u);
  EXPECT_EQ(tokens[7].loc.column, 1u);
}

TEST(ParseLexer, KeywordsAreCaseSensitive) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("error Error TRUE true up", diags);
  EXPECT_EQ(kinds(tokens), (std::vector<TokenKind>{TokenKind::KwError, TokenKind::Identifier,
                                                   TokenKind::Identifier, TokenKind::KwTrue,
                                                   TokenKind::KwUp, TokenKind::EndOfFile}));
  EXPECT_TRUE(is_soft_keyword(TokenKind::KwError));
  EXPECT_TRUE(is_soft_keyword(TokenKind::KwUp));
  EXPECT_FALSE(is_soft_keyword(TokenKind::KwEnd));
}

TEST(ParseLexer, ByteOrderMarkAndCrLf) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("\xEF\xBB\xBFpackage\r\n  p", diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].loc.line, 1u);
  EXPECT_EQ(tokens[0].loc.column, 1u);
  EXPECT_EQ(tokens[1].loc.line, 2u);
  EXPECT_EQ(tokens[1].loc.column, 3u);
}

TEST(ParseLexer, Numbers) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("42 3.25 .5 1e3 2.5E-2 7. 9223372036854775807", diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(tokens.size(), 8u);
  EXPECT_EQ(tokens[0].kind, TokenKind::Int);
  EXPECT_EQ(tokens[0].int_value, 42);
  EXPECT_EQ(tokens[1].kind, TokenKind::Float);
  EXPECT_DOUBLE_EQ(tokens[1].float_value, 3.25);
  EXPECT_EQ(tokens[2].kind, TokenKind::Float);
  EXPECT_DOUBLE_EQ(tokens[2].float_value, 0.5);
  EXPECT_EQ(tokens[3].kind, TokenKind::Float);
  EXPECT_DOUBLE_EQ(tokens[3].float_value, 1000.0);
  EXPECT_EQ(tokens[4].kind, TokenKind::Float);
  EXPECT_DOUBLE_EQ(tokens[4].float_value, 0.025);
  EXPECT_EQ(tokens[5].kind, TokenKind::Float);
  EXPECT_DOUBLE_EQ(tokens[5].float_value, 7.0);
  EXPECT_EQ(tokens[6].kind, TokenKind::Int);
  EXPECT_EQ(tokens[6].int_value, 9223372036854775807);
}

TEST(ParseLexer, IntegerOverflowIsAnError) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("x = 9223372036854775808", diags);
  EXPECT_EQ(first_error(diags),
            "1:5: integer literal '9223372036854775808' is too large (the largest int is "
            "9223372036854775807)");
  EXPECT_EQ(tokens[2].kind, TokenKind::Int);
}

TEST(ParseLexer, StringEscapes) {
  Diagnostics diags;
  std::vector<Token> tokens = lex(R"("a\b\t\n\f\r\"\'\\z" "\101\7\60x" "\u00e9\u0041")", diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].kind, TokenKind::String);
  EXPECT_EQ(tokens[0].string_value, "a\b\t\n\f\r\"'\\z");
  EXPECT_EQ(tokens[1].string_value, std::string("A\a0x"));
  EXPECT_EQ(tokens[2].string_value,
            "\xC3\xA9"
            "A");
  EXPECT_EQ(tokens[0].text, R"("a\b\t\n\f\r\"\'\\z")");
}

// A string holds UTF-8 text: octal escapes are characters U+0000 to U+00FF (as in Java, whose
// escapes BIP2 takes), and a UTF-16 surrogate pair of \u escapes is one character.
TEST(ParseLexer, StringsAreUtf8) {
  Diagnostics diags;
  std::vector<Token> tokens = lex(R"("\351\377" "\uD83D\uDE00" )"
                                  "\"\xC3\xA9\xF0\x9F\x98\x80\xEF\xBF\xBF\"",
                                  diags);
  EXPECT_FALSE(diags.has_errors()) << first_error(diags);
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].string_value, "\xC3\xA9\xC3\xBF");
  EXPECT_EQ(tokens[1].string_value, "\xF0\x9F\x98\x80");
  EXPECT_EQ(tokens[2].string_value, "\xC3\xA9\xF0\x9F\x98\x80\xEF\xBF\xBF");
}

TEST(ParseLexer, BytesThatAreNotUtf8InAStringAreErrors) {
  // A Latin-1 byte, an overlong '/', an encoded surrogate, a code point past U+10FFFF and a
  // sequence cut short by the closing quote, each reported at its byte.
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {"x = \"caf\xE9\"", "1:9: string literal holds the byte '\\xE9', which is not UTF-8"},
           {"\"\xC0\xAF\"", "1:2: string literal holds the byte '\\xC0', which is not UTF-8"},
           {"\"a\xED\xA0\x80\"", "1:3: string literal holds the byte '\\xED', which is not UTF-8"},
           {"\"\xF4\x90\x80\x80\"",
            "1:2: string literal holds the byte '\\xF4', which is not UTF-8"},
           {"\"\xE2\x82\"", "1:2: string literal holds the byte '\\xE2', which is not UTF-8"},
       }) {
    Diagnostics diags;
    lex(text, diags);
    EXPECT_EQ(first_error(diags).substr(0, expected.size()), expected) << first_error(diags);
  }
}

TEST(ParseLexer, HalfASurrogatePairIsAnError) {
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {R"("\uD800")",
            "1:2: invalid escape sequence '\\uD800': half of a UTF-16 surrogate pair"},
           {R"("\uDC00\uD800")", "1:2: invalid escape sequence '\\uDC00': half of a UTF-16"},
           {R"("\uD800\u0041")", "1:2: invalid escape sequence '\\uD800': half of a UTF-16"},
       }) {
    Diagnostics diags;
    std::vector<Token> tokens = lex(text, diags);
    EXPECT_EQ(first_error(diags).substr(0, expected.size()), expected) << first_error(diags);
  }
  Diagnostics diags;
  std::vector<Token> tokens = lex(R"("\uD800\u0041")", diags);
  EXPECT_EQ(tokens[0].string_value, "A");  // the escape after the lone half is kept
}

TEST(ParseLexer, InvalidEscape) {
  Diagnostics diags;
  lex("  \"a\\qb\"", diags);
  EXPECT_EQ(first_error(diags), "1:5: invalid escape sequence '\\q' in string literal");
}

TEST(ParseLexer, Comments) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("a // one\nb /* two\n three */ c// end", diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[1].text, "b");
  EXPECT_EQ(tokens[1].loc.line, 2u);
  EXPECT_EQ(tokens[2].text, "c");
  EXPECT_EQ(tokens[2].loc.line, 3u);
  EXPECT_EQ(tokens[2].loc.column, 11u);
}

TEST(ParseLexer, UnterminatedCommentAndStringAreReportedAtTheirStart) {
  {
    Diagnostics diags;
    std::vector<Token> tokens = lex("a\n  /* open\n\n", diags);
    EXPECT_EQ(first_error(diags), "2:3: unterminated comment");
    EXPECT_EQ(tokens.back().kind, TokenKind::EndOfFile);
  }
  {
    Diagnostics diags;
    std::vector<Token> tokens = lex("x = \"abc\n def", diags);
    EXPECT_EQ(first_error(diags), "1:5: unterminated string literal");
    EXPECT_EQ(tokens[2].kind, TokenKind::Invalid);
  }
}

TEST(ParseLexer, Operators) {
  Diagnostics diags;
  std::vector<Token> tokens =
      lex("( ) { } , ' . ; : @ = < > <= >= == != && || ! ~ + - * / % & | ^", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_EQ(kinds(tokens),
            (std::vector<TokenKind>{
                TokenKind::LParen, TokenKind::RParen,   TokenKind::LBrace, TokenKind::RBrace,
                TokenKind::Comma,  TokenKind::Quote,    TokenKind::Dot,    TokenKind::Semicolon,
                TokenKind::Colon,  TokenKind::AtSign,   TokenKind::Assign, TokenKind::Lt,
                TokenKind::Gt,     TokenKind::Le,       TokenKind::Ge,     TokenKind::EqEq,
                TokenKind::NotEq,  TokenKind::AndAnd,   TokenKind::OrOr,   TokenKind::Not,
                TokenKind::Tilde,  TokenKind::Plus,     TokenKind::Minus,  TokenKind::Star,
                TokenKind::Slash,  TokenKind::Percent,  TokenKind::Amp,    TokenKind::Pipe,
                TokenKind::Caret,  TokenKind::EndOfFile}));
  EXPECT_EQ(spelling(TokenKind::Le), "<=");
  EXPECT_EQ(spelling(TokenKind::KwEnd), "end");
}

TEST(ParseLexer, PrimeAfterName) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("x' = 2.0;", diags);
  EXPECT_EQ(kinds(tokens),
            (std::vector<TokenKind>{TokenKind::Identifier, TokenKind::Quote, TokenKind::Assign,
                                    TokenKind::Float, TokenKind::Semicolon, TokenKind::EndOfFile}));
}

TEST(ParseLexer, UnexpectedCharacter) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("a\n  # b $", diags);
  ASSERT_EQ(diags.error_count(), 2u);
  EXPECT_EQ(first_error(diags), "2:3: unexpected character '#'");
  EXPECT_EQ(diags.all()[1].message, "unexpected character '$'");
  EXPECT_EQ(tokens[1].kind, TokenKind::Invalid);
  EXPECT_EQ(tokens[2].text, "b");
  EXPECT_EQ(tokens[2].loc.column, 5u);
}

TEST(ParseLexer, NonAsciiCharactersCountAsOneColumn) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("/* \xC3\xA9t\xC3\xA9 */ x \x01", diags);
  EXPECT_EQ(tokens[0].loc.column, 11u);
  EXPECT_EQ(first_error(diags), "1:13: unexpected character '\\x01'");
}

TEST(ParseLexer, DescribeTokens) {
  Diagnostics diags;
  std::vector<Token> tokens = lex("end , x \"s\"", diags);
  EXPECT_EQ(describe(tokens[0]), "'end'");
  EXPECT_EQ(describe(tokens[1]), "','");
  EXPECT_EQ(describe(tokens[2]), "'x'");
  EXPECT_EQ(describe(tokens[3]), "string \"s\"");
  EXPECT_EQ(describe(tokens[4]), "end of file");
}

}  // namespace
}  // namespace smcbip::bipc::detail
