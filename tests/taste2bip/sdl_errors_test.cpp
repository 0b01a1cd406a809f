// The SDL reader's located errors, and its robustness on broken or hostile input.
#include <gtest/gtest.h>

#include <random>

#include "sdl_test_support.h"

namespace smcbip::taste2bip::sdl {
namespace {

using testing::in_transition;
using testing::read_errors;

TEST(SdlErrors, MissingSemicolonAfterNextstate) {
  EXPECT_EQ(read_errors("process p;\n  start;\n    nextstate Idle\n  state Idle;\n  endstate;\n"
                        "endprocess p;\n"),
            "test.pr:4:3: error: expected ';' after 'nextstate Idle', got 'state'\n");
}

TEST(SdlErrors, MissingEndprocess) {
  EXPECT_EQ(read_errors("process p;\n  start;\n    stop;\n"),
            "test.pr:4:1: error: expected 'endprocess' closing process p, got end of file\n");
}

TEST(SdlErrors, UnknownDeclarationIsNamed) {
  EXPECT_EQ(read_errors("process p;\n  newtype T endnewtype;\n  start; stop;\nendprocess;\n"),
            "test.pr:2:3: error: 'newtype' is not supported by this reader (expected 'dcl', "
            "'timer', 'procedure', 'start', 'state', 'connection' or 'endprocess')\n");
}

TEST(SdlErrors, UnsupportedActionEndsTheTransitionWithAnError) {
  EXPECT_EQ(read_errors(in_transition("create q;\nnextstate -;")),
            "test.pr:4:1: error: 'create' is not supported by this reader (expected an action)\n");
}

TEST(SdlErrors, BadExpressionAndMissingAssign) {
  EXPECT_EQ(read_errors(in_transition("task x := ;\ntask y 3;\nnextstate -;")),
            "test.pr:4:11: error: expected an expression, got ';'\n"
            "test.pr:5:8: error: expected ':=' in an assignment, got '3'\n");
}

TEST(SdlErrors, DecisionAnswers) {
  EXPECT_EQ(read_errors(in_transition("decision x;\n (1) stop;\n 2: stop;\nenddecision;")),
            "test.pr:5:6: error: expected ':' after the answer, got 'stop'\n"
            "test.pr:6:2: error: expected an answer '(...):', 'else:' or 'enddecision', got '2'\n");
}

TEST(SdlErrors, UnterminatedStringAndComment) {
  EXPECT_EQ(read_errors("process p;\n start;\n task 'oops;\n"),
            "test.pr:3:7: error: unterminated string: expected a closing quote before end of "
            "file\n");
  EXPECT_EQ(read_errors("/* never closed\nprocess p;"),
            "test.pr:1:1: error: unterminated comment: expected '*/' before end of file\n");
}

TEST(SdlErrors, UnexpectedCharacters) {
  EXPECT_EQ(read_errors("process p; start; task x := 1 # 2; stop; endprocess;"),
            "test.pr:1:31: error: unexpected character '#' (not part of SDL-PR)\n"
            "test.pr:1:33: error: expected ';' after 'task', got '2'\n");
}

TEST(SdlErrors, TopLevel) {
  EXPECT_EQ(read_errors("state s;"),
            "test.pr:1:1: error: expected 'use', 'system', 'process' or 'procedure', got "
            "'state'\n");
}

std::size_t error_count(const std::string& text) {
  bipc::Diagnostics diags;
  read_sdl(text, 0, diags);
  testing::expect_located_within(diags, text);
  return diags.error_count();
}

TEST(SdlRobustness, ErrorsStopAfterTwenty) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += "bogus;\n";
  EXPECT_EQ(error_count(text), 20u);
}

TEST(SdlRobustness, MegabyteOfNuls) { EXPECT_EQ(error_count(std::string(1 << 20, '\0')), 1u); }

TEST(SdlRobustness, RandomBytes) {
  std::mt19937 rng(2026);  // fixed seed: the same bytes every run
  for (int round = 0; round < 50; ++round) {
    std::string text(4096, ' ');
    for (char& c : text) c = static_cast<char>(rng() & 0xFF);
    EXPECT_LE(error_count(text), 20u);
  }
}

TEST(SdlRobustness, RandomTokenSoup) {
  static const char* const kWords[] = {"process",
                                       "state",
                                       "input",
                                       "decision",
                                       "(",
                                       ")",
                                       ":",
                                       ";",
                                       "task",
                                       "x",
                                       ":=",
                                       "1",
                                       "+",
                                       "else",
                                       "enddecision",
                                       "endstate",
                                       "{",
                                       "}",
                                       "if",
                                       "then",
                                       "fi",
                                       "for",
                                       "in",
                                       "endfor",
                                       "substructure",
                                       "endsubstructure",
                                       "procedure",
                                       "endprocedure",
                                       "start",
                                       "nextstate",
                                       "-",
                                       "*",
                                       ",",
                                       "'s'",
                                       "call"};
  std::mt19937 rng(7);
  for (int round = 0; round < 200; ++round) {
    std::string text;
    for (int i = 0; i < 300; ++i) {
      text += kWords[rng() % (sizeof kWords / sizeof kWords[0])];
      text += ' ';
    }
    EXPECT_LE(error_count(text), 20u);
  }
}

TEST(SdlRobustness, DeepNestingIsBounded) {
  const std::string parens = in_transition("task x := " + std::string(100000, '(') + "1;");
  EXPECT_EQ(error_count(parens), 1u);
  const std::string braces = in_transition("task x := " + std::string(100000, '{') + "1;");
  EXPECT_EQ(error_count(braces), 1u);
  std::string nots = "task x := ";
  for (int i = 0; i < 100000; ++i) nots += "not ";
  EXPECT_EQ(error_count(in_transition(nots + "a;")), 1u);
  std::string decisions;
  for (int i = 0; i < 10000; ++i) decisions += "decision a; (1): ";
  EXPECT_EQ(error_count(in_transition(decisions)), 1u);
  std::string states = "process p;";
  for (int i = 0; i < 10000; ++i) states += "state s; substructure ";
  EXPECT_EQ(error_count(states), 1u);
  std::string choices = "task x := ";
  for (int i = 0; i < 100000; ++i) choices += "a:";
  EXPECT_EQ(error_count(in_transition(choices + "1;")), 1u);
}

TEST(SdlRobustness, NestingWithinTheLimitReads) {
  const std::string text =
      in_transition("task x := " + std::string(50, '(') + "1" + std::string(50, ')') + ";");
  EXPECT_EQ(error_count(text), 0u);
}

// An 'é' takes two columns, as in every reader of taste2bip.
TEST(SdlErrors, ColumnsCountBytesAsInEveryTasteReader) {
  EXPECT_EQ(read_errors("process p; start; task x := '\xC3\xA9' # 1; endprocess;"),
            "test.pr:1:34: error: unexpected character '#' (not part of SDL-PR)\n"
            "test.pr:1:36: error: expected ';' after 'task', got '1'\n");
}

}  // namespace
}  // namespace smcbip::taste2bip::sdl
