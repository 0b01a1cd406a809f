// The SDL reader on systems, blocks, processes, procedures and states, tree by tree.
#include <gtest/gtest.h>

#include "sdl_test_support.h"

namespace smcbip::taste2bip::sdl {
namespace {

using testing::read_ok;
using testing::show;

TEST(SdlStructure, SystemWithSignalsChannelsBlockAndReferencedProcess) {
  const SdlFile file = read_ok(R"(/* CIF Keep Specific Geode ASNFilename 'dataview-uniq.asn' */
USE Datamodel;
SYSTEM challenge;
    use dv comment 'dataview-uniq.asn';
    SIGNAL run; signal cmd (Base_T, T_Int);
    CHANNEL c
        FROM ENV TO challenge WITH run, cmd;
        FROM challenge TO ENV WITH run;
    ENDCHANNEL;
    BLOCK challenge;
        SIGNALROUTE r
            FROM ENV TO challenge WITH run, cmd;
        CONNECT c and r;
        PROCESS challenge REFERENCED;
    ENDBLOCK;
ENDSYSTEM;
)");
  ASSERT_EQ(file.uses.size(), 1u);
  EXPECT_EQ(file.uses[0].package, "Datamodel");
  EXPECT_EQ(file.uses[0].at.line, 2u);
  EXPECT_EQ(file.uses[0].at.column, 1u);
  ASSERT_EQ(file.systems.size(), 1u);
  const System& system = file.systems[0];
  EXPECT_EQ(system.name, "challenge");
  ASSERT_EQ(system.uses.size(), 1u);
  EXPECT_EQ(system.uses[0].package, "dv");
  EXPECT_EQ(system.uses[0].comment, "dataview-uniq.asn");
  ASSERT_EQ(system.signals.size(), 2u);
  EXPECT_EQ(system.signals[0].name, "run");
  EXPECT_TRUE(system.signals[0].parameter_types.empty());
  EXPECT_EQ(system.signals[1].name, "cmd");
  EXPECT_EQ(system.signals[1].parameter_types, (std::vector<std::string>{"Base_T", "T_Int"}));
  EXPECT_EQ(system.signals[1].at.line, 5u);
  EXPECT_EQ(system.signals[1].at.column, 24u);
  ASSERT_EQ(system.channels.size(), 1u);
  ASSERT_EQ(system.channels[0].paths.size(), 2u);
  EXPECT_EQ(system.channels[0].paths[0].from, "ENV");
  EXPECT_EQ(system.channels[0].paths[0].to, "challenge");
  EXPECT_EQ(system.channels[0].paths[0].signals, (std::vector<std::string>{"run", "cmd"}));
  EXPECT_EQ(system.channels[0].paths[1].to, "ENV");
  ASSERT_EQ(system.blocks.size(), 1u);
  const Block& block = system.blocks[0];
  ASSERT_EQ(block.routes.size(), 1u);
  EXPECT_EQ(block.routes[0].name, "r");
  ASSERT_EQ(block.connections.size(), 1u);
  EXPECT_EQ(block.connections[0].channel, "c");
  EXPECT_EQ(block.connections[0].routes, (std::vector<std::string>{"r"}));
  ASSERT_EQ(block.processes.size(), 1u);
  EXPECT_TRUE(block.processes[0].is_referenced);
  EXPECT_EQ(block.processes[0].name, "challenge");
}

TEST(SdlStructure, ProcessDeclarations) {
  const SdlFile file = read_ok(R"(PROCESS p;
    DCL a MyInteger := 4;
    dcl e, g MyChoice;
    dcl x T1 := 1, y T2;
    TIMER t1; timer t2, t3;
    START;
        NEXTSTATE Wait;
    STATE Wait;
    ENDSTATE;
ENDPROCESS p;
)");
  ASSERT_EQ(file.processes.size(), 1u);
  const Body& body = file.processes[0].body;
  ASSERT_EQ(body.variables.size(), 5u);
  EXPECT_EQ(body.variables[0].name, "a");
  EXPECT_EQ(body.variables[0].type, "MyInteger");
  ASSERT_TRUE(body.variables[0].initial.has_value());
  EXPECT_EQ(show(*body.variables[0].initial), "4");
  EXPECT_EQ(body.variables[1].name, "e");
  EXPECT_EQ(body.variables[1].type, "MyChoice");
  EXPECT_EQ(body.variables[2].name, "g");
  EXPECT_EQ(body.variables[2].type, "MyChoice");
  EXPECT_FALSE(body.variables[2].initial.has_value());
  EXPECT_EQ(body.variables[3].type, "T1");
  EXPECT_EQ(body.variables[4].name, "y");
  EXPECT_EQ(body.variables[4].type, "T2");
  EXPECT_EQ(body.variables[4].at.line, 4u);
  EXPECT_EQ(body.variables[4].at.column, 20u);
  ASSERT_EQ(body.timers.size(), 3u);
  EXPECT_EQ(body.timers[2].name, "t3");
  ASSERT_EQ(body.starts.size(), 1u);
  ASSERT_EQ(body.starts[0].transition.actions.size(), 1u);
  EXPECT_EQ(body.starts[0].transition.actions[0].kind, Action::Kind::NextState);
  EXPECT_EQ(body.starts[0].transition.actions[0].name, "Wait");
  ASSERT_EQ(body.states.size(), 1u);
  EXPECT_EQ(body.states[0].names, (std::vector<std::string>{"Wait"}));
}

TEST(SdlStructure, ProcessTypeAndInstance) {
  const SdlFile file = read_ok(
      "process type T;\n start; stop;\nendprocess type T;\n"
      "process p : T;\n");
  ASSERT_EQ(file.processes.size(), 2u);
  EXPECT_TRUE(file.processes[0].is_type);
  EXPECT_EQ(file.processes[0].name, "T");
  EXPECT_EQ(file.processes[1].instance_of, "T");
}

TEST(SdlStructure, Procedures) {
  const SdlFile file = read_ok(R"(system s;
  PROCEDURE pow COMMENT '#c_predef';
    FPAR IN a T_UInt32, IN b T_UInt32, IN/OUT res T_UInt32;
  EXTERNAL;
endsystem;
process p;
  procedure multireturn;
    fpar in a, b MyInteger, out r MyInteger;
    returns MyInteger;
    DCL l MyInteger;
    START;
      return a * b;
  endprocedure;
  procedure named; returns res T; start; return; endprocedure named;
endprocess;
)");
  ASSERT_EQ(file.systems.size(), 1u);
  ASSERT_EQ(file.systems[0].procedures.size(), 1u);
  const Procedure& pow = file.systems[0].procedures[0];
  EXPECT_TRUE(pow.is_external);
  EXPECT_EQ(pow.comment, "#c_predef");
  ASSERT_EQ(pow.parameters.size(), 3u);
  EXPECT_EQ(pow.parameters[2].name, "res");
  EXPECT_EQ(pow.parameters[2].direction, FormalParameter::Direction::InOut);
  EXPECT_EQ(pow.parameters[0].direction, FormalParameter::Direction::In);

  ASSERT_EQ(file.processes.size(), 1u);
  const auto& procedures = file.processes[0].body.procedures;
  ASSERT_EQ(procedures.size(), 2u);
  const Procedure& multi = procedures[0];
  EXPECT_FALSE(multi.is_external);
  ASSERT_EQ(multi.parameters.size(), 3u);
  EXPECT_EQ(multi.parameters[1].name, "b");
  EXPECT_EQ(multi.parameters[1].type, "MyInteger");
  EXPECT_EQ(multi.parameters[1].direction, FormalParameter::Direction::In);
  EXPECT_EQ(multi.parameters[2].direction, FormalParameter::Direction::Out);
  EXPECT_EQ(multi.return_type, "MyInteger");
  ASSERT_EQ(multi.body.variables.size(), 1u);
  ASSERT_EQ(multi.body.starts.size(), 1u);
  const Action& ret = multi.body.starts[0].transition.actions.at(0);
  EXPECT_EQ(ret.kind, Action::Kind::Return);
  ASSERT_TRUE(ret.value.has_value());
  EXPECT_EQ(show(*ret.value), "(* a b)");
  EXPECT_EQ(procedures[1].return_name, "res");
  EXPECT_EQ(procedures[1].return_type, "T");
  EXPECT_FALSE(procedures[1].body.starts.at(0).transition.actions.at(0).value.has_value());
}

TEST(SdlStructure, StateForms) {
  const SdlFile file = read_ok(R"(process p;
  state S, T;
    input sig(p1, p2), other;
      nextstate -;
    input *;
      nextstate S;
    save a, b;
  endstate;
  state *;
    provided x > 1;
      priority 2;
      nextstate S via E;
  endstate;
  state *(A, B);
    save *;
  endstate;
  state S via entry_point comment 'why';
  endstate S;
endprocess p;
)");
  const auto& states = file.processes.at(0).body.states;
  ASSERT_EQ(states.size(), 4u);
  EXPECT_EQ(states[0].names, (std::vector<std::string>{"S", "T"}));
  ASSERT_EQ(states[0].inputs.size(), 2u);
  const Input& input = states[0].inputs[0];
  ASSERT_EQ(input.signals.size(), 2u);
  EXPECT_EQ(input.signals[0].name, "sig");
  EXPECT_EQ(input.signals[0].parameters, (std::vector<std::string>{"p1", "p2"}));
  EXPECT_EQ(input.signals[1].name, "other");
  EXPECT_EQ(input.at.line, 3u);
  EXPECT_EQ(input.at.column, 5u);
  EXPECT_EQ(input.transition.actions.at(0).name, "-");
  EXPECT_TRUE(states[0].inputs[1].is_any);
  EXPECT_EQ(states[0].saves, (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(states[1].is_any);
  EXPECT_TRUE(states[1].names.empty());
  ASSERT_EQ(states[1].continuous.size(), 1u);
  EXPECT_EQ(show(states[1].continuous[0].condition), "(> x 1)");
  ASSERT_TRUE(states[1].continuous[0].priority.has_value());
  EXPECT_EQ(show(*states[1].continuous[0].priority), "2");
  const Action& next = states[1].continuous[0].transition.actions.at(0);
  EXPECT_EQ(next.name, "S");
  EXPECT_EQ(next.via, "E");
  EXPECT_TRUE(states[2].is_any);
  EXPECT_EQ(states[2].except, (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(states[2].saves, (std::vector<std::string>{"*"}));
  EXPECT_EQ(states[3].via, "entry_point");
  EXPECT_EQ(states[3].comment, "why");
}

TEST(SdlStructure, NestedStatesWithEntryAndExitPoints) {
  const SdlFile file = read_ok(R"(process p;
  state went;
  substructure
    in (short);
    out (e2, e1);
    procedure entry;
      start;
        call writeln('enter');
        return;
    endprocedure;
    start;
      nextstate gone;
    start short;
      nextstate gone;
    state gone;
      input dd;
        return e1;
    endstate;
  endsubstructure;
  state went;
    connect e1, e2;
      nextstate went;
    connect;
      stop;
  endstate;
  state aggregation par;
  substructure
    state a; substructure start; nextstate x; state x; endstate; endsubstructure;
  endsubstructure;
endprocess p;
)");
  const Body& body = file.processes.at(0).body;
  ASSERT_EQ(body.composite_states.size(), 2u);
  const CompositeState& went = body.composite_states[0];
  EXPECT_EQ(went.name, "went");
  EXPECT_FALSE(went.is_aggregation);
  EXPECT_EQ(went.entry_points, (std::vector<std::string>{"short"}));
  EXPECT_EQ(went.exit_points, (std::vector<std::string>{"e2", "e1"}));
  ASSERT_EQ(went.body.procedures.size(), 1u);
  EXPECT_EQ(went.body.procedures[0].name, "entry");
  ASSERT_EQ(went.body.starts.size(), 2u);
  EXPECT_EQ(went.body.starts[0].entry_point, "");
  EXPECT_EQ(went.body.starts[1].entry_point, "short");
  ASSERT_EQ(went.body.states.size(), 1u);
  const Action& ret = went.body.states[0].inputs.at(0).transition.actions.at(0);
  EXPECT_EQ(ret.kind, Action::Kind::Return);
  EXPECT_EQ(show(*ret.value), "e1");
  ASSERT_EQ(body.states.size(), 1u);
  ASSERT_EQ(body.states[0].connections.size(), 2u);
  EXPECT_EQ(body.states[0].connections[0].exit_points, (std::vector<std::string>{"e1", "e2"}));
  EXPECT_TRUE(body.states[0].connections[1].exit_points.empty());
  EXPECT_EQ(body.states[0].connections[1].transition.actions.at(0).kind, Action::Kind::Stop);
  const CompositeState& par = body.composite_states[1];
  EXPECT_TRUE(par.is_aggregation);
  ASSERT_EQ(par.body.composite_states.size(), 1u);
  EXPECT_EQ(par.body.composite_states[0].name, "a");
}

TEST(SdlStructure, FloatingLabels) {
  const SdlFile file = read_ok(R"(process p;
  start; join hello;
  connection hello:
    nextstate -;
  endconnection;
  connection there: label3: nextstate S; endconnection there;
endprocess p;
)");
  const Body& body = file.processes.at(0).body;
  ASSERT_EQ(body.labels.size(), 2u);
  EXPECT_EQ(body.labels[0].name, "hello");
  EXPECT_EQ(body.labels[0].at.line, 3u);
  EXPECT_EQ(body.labels[1].transition.actions.at(0).kind, Action::Kind::Label);
  EXPECT_EQ(body.labels[1].transition.actions.at(0).name, "label3");
  EXPECT_EQ(body.starts.at(0).transition.actions.at(0).kind, Action::Kind::Join);
}

TEST(SdlStructure, KeywordsAreCaseInsensitiveNamesKeepTheirSpelling) {
  const SdlFile file = read_ok("PrOcEsS MyProc;\n StArT;\n NextState Idle_State;\nEndProcess;\n");
  ASSERT_EQ(file.processes.size(), 1u);
  EXPECT_EQ(file.processes[0].name, "MyProc");
  EXPECT_EQ(file.processes[0].body.starts.at(0).transition.actions.at(0).name, "Idle_State");
}

TEST(SdlStructure, CommentsAreSkipped) {
  const SdlFile file = read_ok(
      "/* CIF PROCESS (1, 2) */ process p; -- a line comment\n"
      "-- ends at the next -- dcl x T; -- rest of the line\n"
      "/* multi\nline */ start; nextstate s; endprocess;");
  ASSERT_EQ(file.processes.size(), 1u);
  EXPECT_EQ(file.processes[0].body.variables.size(), 1u);
  EXPECT_EQ(file.processes[0].body.starts.at(0).at.line, 4u);
  EXPECT_EQ(file.processes[0].body.starts.at(0).at.column, 9u);
}

TEST(SdlStructure, InputsWithEnablingConditionsAndSpontaneousTransitions) {
  const SdlFile file = read_ok(R"(process p(1, 2);
  state S;
    input go(x);
    provided x > 0;
      nextstate -;
    input none;
      nextstate T;
    provided ready;
      stop;
  endstate;
  state T;
    connect *;
      nextstate S;
  endstate;
endprocess p;
)");
  ASSERT_EQ(file.processes.size(), 1u);
  const Process& process = file.processes[0];
  ASSERT_TRUE(process.initial_instances.has_value());
  ASSERT_TRUE(process.maximum_instances.has_value());
  EXPECT_EQ(show(*process.initial_instances), "1");
  EXPECT_EQ(show(*process.maximum_instances), "2");
  const State& s = process.body.states.at(0);
  ASSERT_EQ(s.inputs.size(), 2u);
  ASSERT_TRUE(s.inputs[0].enabling.has_value());
  EXPECT_EQ(show(*s.inputs[0].enabling), "(> x 0)");
  EXPECT_EQ(s.inputs[0].transition.actions.at(0).name, "-");
  EXPECT_EQ(s.inputs[1].signals.at(0).name, "none");
  EXPECT_FALSE(s.inputs[1].enabling.has_value());
  ASSERT_EQ(s.continuous.size(), 1u);
  EXPECT_EQ(show(s.continuous[0].condition), "ready");
  const State& t = process.body.states.at(1);
  EXPECT_EQ(t.connections.at(0).exit_points, (std::vector<std::string>{"*"}));
}

TEST(SdlStructure, ChannelWithoutDelayAndNestedBlocks) {
  const SdlFile file = read_ok(R"(system s;
  channel c nodelay from env to b with x; endchannel c;
  block b;
    signal inner;
    block b2 referenced;
    procedure q; external;
  endblock b;
endsystem s;
)");
  const System& system = file.systems.at(0);
  EXPECT_TRUE(system.channels.at(0).no_delay);
  const Block& block = system.blocks.at(0);
  EXPECT_EQ(block.signals.at(0).name, "inner");
  ASSERT_EQ(block.blocks.size(), 1u);
  EXPECT_TRUE(block.blocks[0].is_referenced);
  EXPECT_TRUE(block.procedures.at(0).is_external);
}

}  // namespace
}  // namespace smcbip::taste2bip::sdl
