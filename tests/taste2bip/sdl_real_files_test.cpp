// The SDL reader on the shared TASTE designs (ESROCOS, OpenGEODE's test suite, kazoo, SAMV71):
// every .pr file reads without diagnostics, each construct keyword becomes a node, and mutants of
// the files read with bounded errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "sdl_test_support.h"
#include "taste2bip/sdl/detail/sdl_lexer.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip::sdl {
namespace {

namespace fs = std::filesystem;

const fs::path kData = test::shared_data_dir();

std::vector<fs::path> pr_files() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(kData, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().extension() == ".pr") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string slurp(const fs::path& path) { return test::file_text(path); }

TEST(SdlRealFiles, EveryPrFileReadsWithoutErrors) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  const std::vector<fs::path> files = pr_files();
  EXPECT_EQ(files.size(), 57u);
  for (const fs::path& path : files) {
    bipc::SourceFiles sources;
    const std::uint32_t file = sources.add(path.string());
    bipc::Diagnostics diags;
    const SdlFile sdl = read_sdl(slurp(path), file, diags);
    EXPECT_TRUE(diags.all().empty()) << diags.format(sources);
    EXPECT_FALSE(sdl.systems.empty() && sdl.processes.empty()) << path << " declares nothing";
  }
}

SdlFile read_data_file(const std::string& relative) {
  bipc::Diagnostics diags;
  SdlFile file = read_sdl(slurp(kData / relative), 0, diags);
  EXPECT_FALSE(diags.has_errors()) << relative;
  return file;
}

TEST(SdlRealFiles, NestedStatesOfOpenGeodeTestNextstate) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  const SdlFile file = read_data_file("taste/esa-opengeode-testsuite/test-nextstate/og.pr");
  ASSERT_EQ(file.systems.size(), 1u);
  const System& system = file.systems[0];
  EXPECT_EQ(system.signals.size(), 2u);
  ASSERT_EQ(system.blocks.size(), 1u);
  ASSERT_EQ(system.blocks[0].processes.size(), 1u);
  const Body& body = system.blocks[0].processes[0].body;
  ASSERT_EQ(body.composite_states.size(), 4u);
  EXPECT_EQ(body.composite_states[0].name, "wait");
  ASSERT_EQ(body.composite_states[0].body.procedures.size(), 1u);
  EXPECT_EQ(body.composite_states[0].body.procedures[0].name, "entry");
  const CompositeState& went = body.composite_states[3];
  EXPECT_EQ(went.name, "went");
  EXPECT_EQ(went.exit_points, (std::vector<std::string>{"e2", "e1"}));
  ASSERT_EQ(went.body.states.size(), 2u);
  EXPECT_EQ(went.body.states[1].inputs.at(1).transition.actions.at(1).kind, Action::Kind::Return);
  ASSERT_EQ(body.labels.size(), 1u);
  EXPECT_EQ(body.labels[0].name, "hello");
  ASSERT_EQ(body.states.size(), 5u);
  EXPECT_TRUE(body.states[0].is_any);
  EXPECT_EQ(body.states[0].except, (std::vector<std::string>{"wait", "went"}));
  const State& went_exits = body.states[4];
  ASSERT_EQ(went_exits.connections.size(), 2u);
  EXPECT_EQ(went_exits.connections[0].exit_points, (std::vector<std::string>{"e1"}));
  EXPECT_EQ(went_exits.connections[0].transition.actions.at(0).kind, Action::Kind::Join);
  EXPECT_EQ(went_exits.comment, "should not be\nan infinite loop");
}

// Entry and exit points of nested states, and a nextstate through an entry point.
TEST(SdlRealFiles, TrafficLightEntryAndExitPoints) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  const SdlFile file =
      read_data_file("taste/esa-opengeode-testsuite/TrafficLight_Basic/controller.pr");
  ASSERT_EQ(file.processes.size(), 1u);
  const Body& body = file.processes[0].body;
  ASSERT_EQ(body.composite_states.size(), 2u);
  const CompositeState& green = body.composite_states[0];
  EXPECT_EQ(green.name, "Green");
  EXPECT_EQ(green.entry_points, (std::vector<std::string>{"short"}));
  EXPECT_EQ(green.exit_points, (std::vector<std::string>{"Go_Orange"}));
  ASSERT_EQ(green.body.starts.size(), 2u);
  EXPECT_EQ(green.body.starts[1].entry_point, "short");
  EXPECT_EQ(green.body.starts[1].transition.actions.at(0).name, "Second_Delay");
  ASSERT_EQ(body.timers.size(), 1u);
  EXPECT_EQ(body.timers[0].name, "clock");
  bool via_short = false;
  for (const State& state : body.states) {
    for (const ExitConnection& connection : state.connections) {
      for (const Action& action : connection.transition.actions) {
        if (action.kind != Action::Kind::Decision) continue;
        for (const Answer& answer : action.decision.answers) {
          for (const Action& last : answer.transition.actions) {
            if (last.kind == Action::Kind::NextState && last.via == "Short") via_short = true;
          }
        }
      }
    }
  }
  EXPECT_TRUE(via_short) << "no 'nextstate Green via Short' read";
}

TEST(SdlRealFiles, KazooOrchestratorTaskOfAsn1Values) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  // The project keeps its SDL under a folder named `work` (TASTE's layout).
  const std::string project = "taste/esa-kazoo/memoryscrub-opengeode";
  const SdlFile file =
      read_data_file(project + "/" + "work" + "/orchestrator/SDL/src/orchestrator.pr");
  ASSERT_EQ(file.processes.size(), 1u);
  const Body& body = file.processes[0].body;
  EXPECT_EQ(body.variables.size(), 14u);
  ASSERT_EQ(body.starts.size(), 1u);
  const Action& task = body.starts[0].transition.actions.at(0);
  ASSERT_EQ(task.kind, Action::Kind::Task);
  EXPECT_EQ(task.task.size(), 23u);
  EXPECT_EQ(task.comment, "This is a comment\nA multiline one, I mean");
}

// Mutated real files (bytes dropped, duplicated or swapped) read with bounded errors: the
// recovery paths of every construct get exercised on realistic text.
TEST(SdlRealFiles, MutatedFilesReadWithBoundedErrors) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  std::mt19937 rng(42);  // fixed seed: the same mutants every run
  for (const fs::path& path : pr_files()) {
    const std::string original = slurp(path);
    if (original.empty()) continue;
    for (int round = 0; round < 20; ++round) {
      std::string text = original;
      for (int edit = 0; edit < 5; ++edit) {
        const std::size_t at = rng() % text.size();
        const std::size_t length = std::min<std::size_t>(1 + rng() % 12, text.size() - at);
        switch (rng() % 3) {
          case 0:
            text.erase(at, length);
            break;
          case 1:
            text.insert(at, text.substr(at, length));
            break;
          default:
            std::swap(text[at], text[rng() % text.size()]);
            break;
        }
        if (text.empty()) text = " ";
      }
      bipc::Diagnostics diags;
      read_sdl(text, 0, diags);
      EXPECT_LE(diags.error_count(), 20u) << path;
      testing::expect_located_within(diags, text);
    }
  }
}

// How many nodes of the tree each keyword opens, to check that nothing was dropped.
class KeywordCounter {
 public:
  std::map<std::string, std::size_t> counts;

  void file(const SdlFile& file) {
    for (const System& system : file.systems) {
      for (const Procedure& procedure : system.procedures) this->procedure(procedure);
      for (const Block& block : system.blocks) this->block(block);
    }
    for (const Process& process : file.processes) this->process(process);
    for (const Procedure& procedure : file.procedures) this->procedure(procedure);
  }

 private:
  void block(const Block& block) {
    counts["connect"] += block.connections.size();
    for (const Process& process : block.processes) this->process(process);
    for (const Procedure& procedure : block.procedures) this->procedure(procedure);
    for (const Block& inner : block.blocks) this->block(inner);
  }
  void process(const Process& process) {
    ++counts["process"];
    body(process.body);
  }
  void procedure(const Procedure& procedure) {
    ++counts["procedure"];
    body(procedure.body);
  }
  void body(const Body& body) {
    for (const Variable& variable : body.variables) {
      if (variable.initial) expr(*variable.initial);
    }
    for (const Procedure& procedure : body.procedures) this->procedure(procedure);
    for (const Start& start : body.starts) {
      ++counts["start"];
      transition(start.transition);
    }
    for (const FloatingLabel& label : body.labels) {
      ++counts["connection"];
      transition(label.transition);
    }
    for (const CompositeState& composite : body.composite_states) {
      ++counts["state"];
      ++counts["substructure"];
      this->body(composite.body);
    }
    for (const State& state : body.states) {
      ++counts["state"];
      for (const Input& input : state.inputs) {
        ++counts["input"];
        transition(input.transition);
      }
      for (const ContinuousSignal& signal : state.continuous) {
        ++counts["provided"];
        expr(signal.condition);
        transition(signal.transition);
      }
      for (const ExitConnection& connection : state.connections) {
        ++counts["connect"];
        transition(connection.transition);
      }
    }
  }
  void transition(const Transition& transition) {
    for (const Action& action : transition.actions) this->action(action);
  }
  void action(const Action& action) {
    for (const Expr& argument : action.arguments) expr(argument);
    if (action.value) expr(*action.value);
    switch (action.kind) {
      case Action::Kind::Task: {
        // A bare assignment list in a for loop reads as a task without the keyword.
        const bool keyword = action.task.empty() || action.task[0].at.line != action.at.line ||
                             action.task[0].at.column != action.at.column;
        if (keyword) ++counts["task"];
        for (const TaskElement& element : action.task) {
          expr(element.target);
          expr(element.value);
          for (const ForLoop& loop : element.loop) {
            ++counts["for"];
            expr(loop.iterable);
            transition(loop.body);
          }
        }
        break;
      }
      case Action::Kind::Output:
        ++counts["output"];
        for (const OutputSignal& signal : action.outputs) {
          for (const Expr& argument : signal.arguments) expr(argument);
        }
        break;
      case Action::Kind::Call:
        ++counts["call"];
        break;
      case Action::Kind::Decision:
        ++counts["decision"];
        expr(action.decision.question);
        for (const Answer& answer : action.decision.answers) {
          for (const RangeCondition& condition : answer.conditions) {
            expr(condition.low);
            expr(condition.high);
          }
          transition(answer.transition);
        }
        break;
      case Action::Kind::Join:
        ++counts["join"];
        break;
      case Action::Kind::NextState:
        ++counts["nextstate"];
        break;
      case Action::Kind::Stop:
        ++counts["stop"];
        break;
      case Action::Kind::Return:
        ++counts["return"];
        break;
      case Action::Kind::Label:
        break;
    }
  }
  void expr(const Expr& e) {
    if (e.kind == Expr::Kind::ProcedureCall) ++counts["call"];
    for (const Expr& operand : e.operands) expr(operand);
  }
};

TEST(SdlRealFiles, EveryKeywordOfTheFileIsANodeOfTheTree) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  static const char* const kKeywords[] = {
      "process", "procedure", "start",   "connection", "state", "substructure",
      "input",   "provided",  "connect", "task",       "for",   "output",
      "call",    "decision",  "join",    "nextstate",  "stop",  "return"};
  for (const fs::path& path : pr_files()) {
    const std::string text = slurp(path);
    bipc::Diagnostics diags;
    detail::ErrorBudget budget(diags, 20);
    std::map<std::string, std::size_t> written;
    for (const detail::Token& token : detail::lex_sdl(text, 0, budget)) {
      if (token.kind == detail::TokenKind::Word) ++written[token.lower];
    }
    KeywordCounter read;
    read.file(read_sdl(text, 0, diags));
    for (const char* keyword : kKeywords) {
      EXPECT_EQ(read.counts[keyword], written[keyword]) << path << ": '" << keyword << "'";
    }
  }
}

}  // namespace
}  // namespace smcbip::taste2bip::sdl
