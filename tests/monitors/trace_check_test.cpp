// Recorded runs that are not in the exchange format: each fault located at its line and
// column, the whole trace read for them, their number capped.
#include "monitors/trace/trace_check.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "monitors/monitors.h"
#include "monitors/trace/detail/trace_reader.h"

namespace smcbip::monitors {
namespace {

constexpr TimeScale kMilliseconds{1e6, 1e9};

constexpr const char* kQueries =
    "P=? [ F[0,10] ch.lost > 0 ]\n"
    "P=? [ G[0,10] ch.idle ]\n";

/// The faults check_trace finds in `trace` (one `line:column: message` each, then `+N` for
/// those not listed), or "(no fault)".
std::string faults(const std::string& trace, const char* queries = kQueries) {
  const ParsedProperties parsed = parse_properties(queries, "p.mtl");
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  std::istringstream in(trace);
  bipc::Diagnostics diagnostics;
  try {
    (void)check_trace(parsed.file, in, "t.jsonl", kMilliseconds, diagnostics);
  } catch (const TraceError& e) {
    std::string out;
    for (const TraceFault& f : e.faults) {
      out += std::to_string(f.line) + ":" + std::to_string(f.column) + ": " + f.message + "\n";
    }
    if (e.more > 0) out += "+" + std::to_string(e.more) + "\n";
    return out;
  }
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.format(parsed.sources);
  return "(no fault)";
}

constexpr const char* kStep0 = R"({"time":0,"places":{"ch":["idle"]},"data":{"ch.lost":0}})";
constexpr const char* kStep1 = R"({"time":4,"places":{"ch":["busy"]},"data":{"ch.lost":1}})";

TEST(TraceCheck, WrongTypedDataValueIsALocatedError) {
  // It was read as NaN: the query was judged as if the value were unknown.
  EXPECT_EQ(faults(std::string(kStep0) + "\n" +
                   R"({"time":4,"places":{"ch":["busy"]},"data":{"ch.lost":"1"}})" + "\n"),
            "2:54: data \"ch.lost\" is a string, expected a number or a boolean\n");
  EXPECT_EQ(faults(R"({"time":0,"places":{"ch":["idle"]},"data":{"ch.lost":null}})"),
            "1:54: data \"ch.lost\" is null, expected a number or a boolean\n");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"time":4,"places":{"ch":"busy"},"data":{}})"),
            "2:41: no data \"ch.lost\", which the first step has\n");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" +
                   R"({"time":4,"places":{"ch":"busy"},"data":{"ch.lost":1}})"),
            "2:26: the places of \"ch\" are not a list of names\n");
  // Data no query reads may be anything (extern data is written null, strings as text).
  EXPECT_EQ(faults(R"({"time":0,"places":{"ch":["idle"]},"data":{"ch.lost":0,"ch.s":"a"}})"),
            "(no fault)");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + kStep1 + "\n" + R"({"end":"deadlock"})"),
            "(no fault)");
}

TEST(TraceCheck, UnknownEndReasonIsALocatedError) {
  // It was taken for a run cut short.
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"end": "crashed"})" + "\n"),
            "2:9: unknown end \"crashed\": expected deadlock, timelock, limit, stopped or error\n");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"end":3})"),
            "2:8: expected \"end\" to be a string, got a number\n");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"end":"error","code":3,"message":"x"})"),
            "(no fault)");
}

TEST(TraceCheck, NulBytesGiveTwentyErrorsAndACount) {
  // A million error lines were feared for a megabyte of NUL bytes; one line of them is one
  // fault, and lines of them give twenty and the count of the others.
  EXPECT_EQ(faults(std::string(1 << 20, '\0')), "1:1: expected a JSON object on one line\n");
  std::string lines;
  for (int i = 0; i < 10000; ++i) lines += std::string(9, '\0') + "\n";
  const std::string found = faults(lines);
  EXPECT_EQ(found.substr(0, 40), "1:1: expected a JSON object on one line\n");
  EXPECT_NE(found.find("20:1: expected a JSON object on one line\n+9980\n"), std::string::npos)
      << found.substr(0, 2000);
}

TEST(TraceCheck, ReadsPastAFaultForMore) {
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"time":"4"})" + "\n" + kStep1 + "\n" +
                   R"({"time":2,"data":{"ch.lost":1},"places":{"ch":[]}})" + "\n" +
                   R"({"end":"limit"})" + "\n{}\n"),
            "2:9: expected a number \"time\", got a string\n"
            "4:9: the time goes back\n"
            "6:1: nothing may follow the end line (line 5)\n");
  EXPECT_EQ(faults(R"({"time":0,"data":{"ch.lost":0},)"),
            "1:32: expected a JSON object on one line\n");
  EXPECT_EQ(faults(""), "1:1: expected at least one step\n");
  EXPECT_EQ(faults("\n\n"), "2:1: expected at least one step\n");  // where the trace ends
}

TEST(TraceCheck, NumberBeyondTheDoublesIsALocatedError) {
  // The JSON reader's out_of_range exception escaped check_trace (found by the trace fuzzer).
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"time":2.2e705,"data":{"ch.lost":1}})"),
            "2:9: a number out of the range of doubles\n");
  EXPECT_EQ(faults(R"({"time":0,"places":{"ch":["idle"]},"data":{"ch.lost":-1e400}})"),
            "1:54: a number out of the range of doubles\n");
}

TEST(TraceCheck, HeaderAndRatesFaultsAreLocated) {
  const std::string header = R"({"header":{"clocks":{"ch.x":{"unit_ns":1000000}}}})";
  EXPECT_EQ(faults(header + "\n" + kStep0 + "\n" +
                   R"({"time":1,"places":{"ch":[]},"data":{"ch.lost":0},"rates":{"ch.x":2}})"),
            "(no fault)");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + header),
            "2:11: the header must be the first line\n");
  EXPECT_EQ(faults(R"({"header":{"clocks":{"ch.x":{"unit_ns":0}}}})" + std::string("\n") + kStep0),
            "1:29: expected clock \"ch.x\" to give its unit as \"unit_ns\" > 0\n");
  EXPECT_EQ(faults(std::string(kStep0) + "\n" + R"({"time":1,"rates":{"ch.x":"2"}})"),
            "2:27: the rate of \"ch.x\" is a string, expected a number\n");
}

TEST(TraceCheck, ErrorTextIsOneLocatedLinePerFault) {
  const TraceError e("t.jsonl", {{2, 9, "the time goes back"}, {3, 1, "expected"}}, 7);
  EXPECT_EQ(e.report(),
            "t.jsonl:2:9: error: the time goes back\n"
            "t.jsonl:3:1: error: expected\n"
            "t.jsonl: error: 7 more errors not shown\n");
  // As an input error of the tools: the first fault, at its place.
  const InputError& input = e;
  EXPECT_EQ(input.describe("smcbip"), "t.jsonl:2:9: error: the time goes back");
}

TEST(TraceCheck, ValueColumnFollowsTheParsedValue) {
  using detail::value_column;
  EXPECT_EQ(value_column(R"({"a":1,"b":{"c" : [1,"}"],"d":2}})", {"b", "d"}), 31u);
  EXPECT_EQ(value_column(R"({"a":1,"a":2})", {"a"}), 12u);  // the last of repeated keys
  EXPECT_EQ(value_column(R"({"\u0061":1})", {"a"}), 11u);
  EXPECT_EQ(value_column(R"( {"a":{"b":1}})", {"a", "c"}), 0u);
  EXPECT_EQ(value_column(R"({"a":"x\"y","b":true})", {"b"}), 17u);
}

}  // namespace
}  // namespace smcbip::monitors
