// The IR data encoding keeps every field: a System with each field set round-trips, and
// changing any one field changes the encoding and survives the round trip.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <limits>

#include "bipc/ir/ir_data.h"
#include "ir_data_test_util.h"

namespace smcbip::bipc {
namespace {

using ir::kNone;
using ir::Op;
using ir::Scope;
using ir::ValueKind;
using ir_data_test::expect_round_trip;
using ir_data_test::sample_system;
using nlohmann::json;

TEST(IrDataFields, SampleSystemRoundTrips) {
  const ir::System s = sample_system();
  expect_round_trip(s, "sample");
  // Spot checks on the decoded value itself, not only on re-encodings of it.
  const ir::System back = ir::from_data(ir::to_data(s));
  const ir::AtomType& t = back.atom_types.at(0);
  EXPECT_EQ(t.transitions.at(0).guard.instrs.at(1).imm.i, std::numeric_limits<std::int64_t>::min());
  EXPECT_TRUE(std::signbit(t.transitions.at(0).action.instrs.at(0).imm.f));
  EXPECT_EQ(t.invariants.at(0).guard.instrs.at(1).imm.f, 1e300);
  EXPECT_EQ(t.ports.at(0).stochastic->custom_file, "cdf.txt");
  EXPECT_EQ(t.transitions.at(0).loc.column, 5u);
  EXPECT_EQ(back.atoms.at(0).params.at(0).f, 0.25);
  EXPECT_EQ(back.compounds.at(1).exported_data.at("yy"),
            std::make_pair(ir::Index{0}, ir::Index{1}));
  EXPECT_EQ(back.code_count, s.code_count);
  EXPECT_EQ(back.strings.at(1), "w\xc3\xb6rld");
}

TEST(IrDataFields, EmptySystemRoundTrips) { expect_round_trip(ir::System{}, "empty"); }

/// One change to one field of the sample; the name says which.
struct Mutation {
  const char* field;
  std::function<void(ir::System&)> apply;
};

ir::AtomType& atom_type(ir::System& s) { return s.atom_types[0]; }
ir::Port& port(ir::System& s) { return s.atom_types[0].ports[0]; }
ir::Transition& transition(ir::System& s) { return s.atom_types[0].transitions[0]; }
ir::ConnectorType& connector_type(ir::System& s) { return s.connector_types[0]; }
ir::Instr& instr(ir::System& s, std::size_t i) { return transition(s).guard.instrs[i]; }
ir::Annotation& annotation(ir::System& s) { return atom_type(s).annotations[0]; }

std::vector<Mutation> system_mutations() {
  return {
      {"root_name", [](ir::System& s) { s.root_name = "Other"; }},
      {"root_type", [](ir::System& s) { s.root_type = "pkg.Other"; }},
      {"strings", [](ir::System& s) { s.strings[2] = "new"; }},
      {"extern_types.name", [](ir::System& s) { s.extern_types[0].name = "pkg.W"; }},
      {"extern_types.backend_name", [](ir::System& s) { s.extern_types[0].backend_name = "W"; }},
      {"extern_types.refines", [](ir::System& s) { s.extern_types[1].refines.clear(); }},
      {"functions.name", [](ir::System& s) { s.functions[0].name = "len"; }},
      {"functions.is_operator", [](ir::System& s) { s.functions[0].is_operator = true; }},
      {"functions.result", [](ir::System& s) { s.functions[0].result.reset(); }},
      {"functions.params",
       [](ir::System& s) {
         s.functions[0].params[0] = {ValueKind::Int, kNone};
       }},
      {"functions.const_params", [](ir::System& s) { s.functions[1].const_params[0] = true; }},
      {"DataType.kind", [](ir::System& s) { s.functions[0].result->kind = ValueKind::String; }},
      {"DataType.extern_type", [](ir::System& s) { s.functions[1].params[0].extern_type = 0; }},
      {"port_types.name", [](ir::System& s) { s.port_types[1].name = "pkg.R"; }},
      {"port_types.params.name", [](ir::System& s) { s.port_types[0].params[0].first = "w"; }},
      {"port_types.params.type",
       [](ir::System& s) { s.port_types[2].params[0].second.kind = ValueKind::String; }},
      {"cpp_includes", [](ir::System& s) { s.cpp_includes.pop_back(); }},
      {"cpp_sources", [](ir::System& s) { s.cpp_sources[0] = "src/other.cpp"; }},
      {"cpp_include_dirs", [](ir::System& s) { s.cpp_include_dirs.push_back("more"); }},
      {"code_count", [](ir::System& s) { ++s.code_count; }},
      {"sites", [](ir::System& s) { s.sites[1].column = 6; }},
      {"source_files", [](ir::System& s) { s.source_files.pop_back(); }},
  };
}

std::vector<Mutation> code_mutations() {
  return {
      {"Instr.op", [](ir::System& s) { instr(s, 2).op = Op::Ge; }},
      {"Instr.kind", [](ir::System& s) { instr(s, 2).kind = ValueKind::Float; }},
      {"Instr.scope", [](ir::System& s) { instr(s, 0).scope = Scope::AtomParam; }},
      {"Instr.arg", [](ir::System& s) { instr(s, 2).arg = 9; }},
      {"Instr.index", [](ir::System& s) { instr(s, 0).index = 1; }},
      {"Instr.site", [](ir::System& s) { instr(s, 2).site = 0; }},
      {"Instr.imm.i", [](ir::System& s) { instr(s, 1).imm.i = 4; }},
      {"Instr.imm.f", [](ir::System& s) { transition(s).action.instrs[0].imm.f = 0.0; }},
      {"Instr.imm.b",
       [](ir::System& s) { atom_type(s).initial_resume->guard.instrs[0].imm.b = false; }},
      {"Instr.imm.i of a non-push op", [](ir::System& s) { instr(s, 2).imm.i = 1; }},
      {"Code.instrs", [](ir::System& s) { transition(s).guard.instrs.pop_back(); }},
      {"Code.id",
       [](ir::System& s) { std::swap(transition(s).guard.id, transition(s).action.id); }},
      {"Annotation.name", [](ir::System& s) { annotation(s).name = "other"; }},
      {"Annotation.params.key", [](ir::System& s) { annotation(s).params[0].first = "k"; }},
      {"Annotation.params.value", [](ir::System& s) { annotation(s).params[1].second = "v"; }},
      {"Annotation.loc.file", [](ir::System& s) { annotation(s).loc.file = 4; }},
      {"Annotation.loc.line", [](ir::System& s) { annotation(s).loc.line = 4; }},
      {"Annotation.loc.column", [](ir::System& s) { annotation(s).loc.column = 4; }},
  };
}

std::vector<Mutation> atom_type_mutations() {
  return {
      {"AtomType.name", [](ir::System& s) { atom_type(s).name = "pkg.B"; }},
      {"AtomType.params", [](ir::System& s) { atom_type(s).params[1].first = "h"; }},
      {"Data.name", [](ir::System& s) { atom_type(s).data[0].name = "y"; }},
      {"Data.type", [](ir::System& s) { atom_type(s).data[0].type.kind = ValueKind::Bool; }},
      {"Data.exported", [](ir::System& s) { atom_type(s).data[0].exported = false; }},
      {"Data.initial_value",
       [](ir::System& s) { atom_type(s).data[0].initial_value.instrs.clear(); }},
      {"Clock.name", [](ir::System& s) { atom_type(s).clocks[0].name = "d"; }},
      {"Clock.unit", [](ir::System& s) { atom_type(s).clocks[0].unit = ir::TimeUnit::Day; }},
      {"places", [](ir::System& s) { atom_type(s).places[1] = "U"; }},
      {"Port.name", [](ir::System& s) { port(s).name = "r"; }},
      {"Port.type", [](ir::System& s) { port(s).type = 2; }},
      {"Port.data", [](ir::System& s) { port(s).data = {1}; }},
      {"Port.exported", [](ir::System& s) { port(s).exported = false; }},
      {"Port.is_extern", [](ir::System& s) { port(s).is_extern = false; }},
      {"Port.policy", [](ir::System& s) { port(s).policy = ir::ExternPolicy::Error; }},
      {"Port.backend_name", [](ir::System& s) { port(s).backend_name = "x"; }},
      {"Port.stochastic", [](ir::System& s) { port(s).stochastic.reset(); }},
      {"Port.annotations", [](ir::System& s) { port(s).annotations.clear(); }},
      {"Stochastic.distribution",
       [](ir::System& s) { port(s).stochastic->distribution = ir::Distribution::Custom; }},
      {"Stochastic.clock", [](ir::System& s) { port(s).stochastic->clock = kNone; }},
      {"Stochastic.params", [](ir::System& s) { port(s).stochastic->params.pop_back(); }},
      {"Stochastic.custom_file", [](ir::System& s) { port(s).stochastic->custom_file = "b"; }},
      {"InterfacePort.name", [](ir::System& s) { atom_type(s).interface[0].name = "pp"; }},
      {"InterfacePort.type", [](ir::System& s) { atom_type(s).interface[0].type = 1; }},
      {"InterfacePort.ports", [](ir::System& s) { atom_type(s).interface[1].ports = {1}; }},
      {"initial_places", [](ir::System& s) { atom_type(s).initial_places = {1}; }},
      {"initial_action", [](ir::System& s) { atom_type(s).initial_action.instrs.pop_back(); }},
      {"initial_resume", [](ir::System& s) { atom_type(s).initial_resume.reset(); }},
      {"Transition.port", [](ir::System& s) { transition(s).port = 1; }},
      {"Transition.from", [](ir::System& s) { transition(s).from = {1}; }},
      {"Transition.to", [](ir::System& s) { transition(s).to = {0}; }},
      {"Transition.guard", [](ir::System& s) { transition(s).guard.instrs.clear(); }},
      {"Transition.action", [](ir::System& s) { transition(s).action.instrs.clear(); }},
      {"Transition.urgency", [](ir::System& s) { transition(s).urgency = ir::Urgency::Lazy; }},
      {"Transition.resume", [](ir::System& s) { transition(s).resume.reset(); }},
      {"Resume.guard", [](ir::System& s) { transition(s).resume->guard.instrs.clear(); }},
      {"Transition.annotations", [](ir::System& s) { transition(s).annotations.clear(); }},
      {"Transition.loc", [](ir::System& s) { transition(s).loc.line = 13; }},
      {"AtomPriority.name", [](ir::System& s) { atom_type(s).priorities[0].name = "q"; }},
      {"AtomPriority.low", [](ir::System& s) { atom_type(s).priorities[0].low = kNone; }},
      {"AtomPriority.high", [](ir::System& s) { atom_type(s).priorities[0].high = 1; }},
      {"AtomPriority.guard",
       [](ir::System& s) { atom_type(s).priorities[0].guard.instrs.clear(); }},
      {"Invariant.name", [](ir::System& s) { atom_type(s).invariants[0].name = "j"; }},
      {"Invariant.at", [](ir::System& s) { atom_type(s).invariants[0].at = true; }},
      {"Invariant.places",
       [](ir::System& s) {
         atom_type(s).invariants[0].places = {0, 1};
       }},
      {"Invariant.guard", [](ir::System& s) { atom_type(s).invariants[0].guard.instrs.clear(); }},
      {"AtomType.annotations", [](ir::System& s) { atom_type(s).annotations.clear(); }},
  };
}

std::vector<Mutation> connector_type_mutations() {
  return {
      {"ConnectorType.name", [](ir::System& s) { connector_type(s).name = "pkg.S"; }},
      {"ConnectorType.ports.name", [](ir::System& s) { connector_type(s).ports[0].first = "c"; }},
      {"ConnectorType.ports.type", [](ir::System& s) { s.connector_types[1].ports[0].second = 1; }},
      {"ConnectorType.data", [](ir::System& s) { connector_type(s).data[0].name = "w"; }},
      {"ConnectorType.export_name", [](ir::System& s) { connector_type(s).export_name = "f"; }},
      {"ConnectorType.export_type", [](ir::System& s) { s.connector_types[1].export_type = 1; }},
      {"ConnectorType.export_data", [](ir::System& s) { connector_type(s).export_data = {1}; }},
      {"DefineNode.port", [](ir::System& s) { connector_type(s).define[0].port = 1; }},
      {"DefineNode.children", [](ir::System& s) { connector_type(s).define[1].children.clear(); }},
      {"DefineNode.trigger", [](ir::System& s) { connector_type(s).define[0].trigger = false; }},
      {"InteractionCode.ports",
       [](ir::System& s) { connector_type(s).interactions[0].ports = {1}; }},
      {"InteractionCode.guard",
       [](ir::System& s) { connector_type(s).interactions[0].guard.instrs.clear(); }},
      {"InteractionCode.up",
       [](ir::System& s) { connector_type(s).interactions[0].up.instrs.clear(); }},
      {"InteractionCode.down",
       [](ir::System& s) { connector_type(s).interactions[0].down.instrs.clear(); }},
      {"InteractionCode.annotations",
       [](ir::System& s) { connector_type(s).interactions[0].annotations.clear(); }},
      {"ConnectorType.resume",
       [](ir::System& s) { connector_type(s).resume = ir::ConnectorType::Resume::Sync; }},
      {"ConnectorType.annotations", [](ir::System& s) { connector_type(s).annotations.clear(); }},
  };
}

std::vector<Mutation> instance_mutations() {
  return {
      {"AtomInstance.path", [](ir::System& s) { s.atoms[0].path = "sub.z"; }},
      {"AtomInstance.type", [](ir::System& s) { s.atoms[1].type = 1; }},
      {"AtomInstance.parent", [](ir::System& s) { s.atoms[0].parent = 0; }},
      {"AtomInstance.annotations", [](ir::System& s) { s.atoms[0].annotations.clear(); }},
      {"Value.kind", [](ir::System& s) { s.atoms[0].params[0].kind = ValueKind::String; }},
      {"Value.b", [](ir::System& s) { s.atoms[0].params[0].b = false; }},
      {"Value.i", [](ir::System& s) { s.atoms[0].params[0].i = 30; }},
      {"Value.f", [](ir::System& s) { s.atoms[0].params[0].f = 0.5; }},
      {"Value.s", [](ir::System& s) { s.atoms[0].params[0].s = "four"; }},
      {"ConnectorInstance.path", [](ir::System& s) { s.connectors[0].path = "sub.q"; }},
      {"ConnectorInstance.type", [](ir::System& s) { s.connectors[1].type = 2; }},
      {"ConnectorInstance.parent", [](ir::System& s) { s.connectors[0].parent = 0; }},
      {"ConnectorInstance.bound", [](ir::System& s) { s.connectors[0].bound[1].clear(); }},
      {"ConnectorInstance.bound_names",
       [](ir::System& s) { s.connectors[0].bound_names[0] = "x"; }},
      {"ConnectorInstance.bound_through_compound",
       [](ir::System& s) { s.connectors[0].bound_through_compound[0] = true; }},
      {"ConnectorInstance.bound_by", [](ir::System& s) { s.connectors[0].bound_by = kNone; }},
      {"ConnectorInstance.bound_by_all", [](ir::System& s) { s.connectors[0].bound_by_all = {}; }},
      {"ConnectorInstance.annotations", [](ir::System& s) { s.connectors[0].annotations.clear(); }},
      {"PortRef.kind",
       [](ir::System& s) { s.connectors[1].bound[0][0].kind = ir::PortRef::Kind::Atom; }},
      {"PortRef.instance", [](ir::System& s) { s.connectors[0].bound[0][0].instance = 1; }},
      {"PortRef.port", [](ir::System& s) { s.connectors[0].bound[0][0].port = 1; }},
      {"PortRef.port of a connector", [](ir::System& s) { s.connectors[1].bound[0][0].port = 8; }},
      {"CompoundInstance.path", [](ir::System& s) { s.compounds[1].path = "sub2"; }},
      {"CompoundInstance.type", [](ir::System& s) { s.compounds[1].type = "pkg.Sub2"; }},
      {"CompoundInstance.parent", [](ir::System& s) { s.compounds[2].parent = 0; }},
      {"CompoundInstance.atoms",
       [](ir::System& s) {
         s.compounds[0].atoms = {0, 1};
       }},
      {"CompoundInstance.compounds", [](ir::System& s) { s.compounds[0].compounds.clear(); }},
      {"CompoundInstance.connectors",
       [](ir::System& s) {
         s.compounds[1].connectors = {0, 1};
       }},
      {"Priority.name", [](ir::System& s) { s.compounds[0].priorities[0].name = "p"; }},
      {"Priority.low", [](ir::System& s) { s.compounds[0].priorities[0].low.connector = 0; }},
      {"Priority.high", [](ir::System& s) { s.compounds[0].priorities[0].high.connector = 1; }},
      {"Priority.guard",
       [](ir::System& s) { s.compounds[0].priorities[0].guard.instrs[0].arg = 1; }},
      {"PatternSide.all_ports",
       [](ir::System& s) { s.compounds[0].priorities[0].low.all_ports = false; }},
      {"PatternSide.ports", [](ir::System& s) { s.compounds[1].priorities[0].low.ports.clear(); }},
      {"CompoundInstance.exported_ports",
       [](ir::System& s) { s.compounds[1].exported_ports.erase("in"); }},
      {"CompoundInstance.exported_ports refs",
       [](ir::System& s) { s.compounds[1].exported_ports["in"][0].port = 0; }},
      {"CompoundInstance.exported_data",
       [](ir::System& s) { s.compounds[1].exported_data["xx"].second = 1; }},
      {"CompoundInstance.annotations", [](ir::System& s) { s.compounds[0].annotations.clear(); }},
  };
}

TEST(IrDataFields, EveryFieldIsEncodedAndDecoded) {
  const ir::System base = sample_system();
  const std::vector<std::uint8_t> base_bytes = ir::to_bytes(base);
  std::vector<Mutation> mutations;
  for (auto list : {system_mutations(), code_mutations(), atom_type_mutations(),
                    connector_type_mutations(), instance_mutations()}) {
    mutations.insert(mutations.end(), list.begin(), list.end());
  }
  for (const Mutation& m : mutations) {
    SCOPED_TRACE(m.field);
    ir::System changed = sample_system();
    m.apply(changed);
    EXPECT_FALSE(ir::to_bytes(changed) == base_bytes) << "the change is not in the encoding";
    expect_round_trip(changed, m.field);
  }
}

// The front end lets a string literal hold bytes that are not UTF-8 (`"caf\xe9"` in a Latin-1
// file); the bytes keep them, although JSON text cannot.
TEST(IrDataFields, StringsThatAreNotUtf8RoundTripAsBytes) {
  ir::System s = sample_system();
  s.strings[2] = "caf\xe9";
  s.atoms[0].path = std::string("a\0b", 3);
  const ir::System back = ir::from_bytes(ir::to_bytes(s));
  EXPECT_EQ(back.strings[2], "caf\xe9");
  EXPECT_EQ(back.atoms[0].path, std::string("a\0b", 3));
  EXPECT_TRUE(ir::to_bytes(back) == ir::to_bytes(s));
}

TEST(IrDataFields, NonFiniteDoublesKeepTheirBits) {
  ir::System s = sample_system();
  const double quiet_nan = std::bit_cast<double>(std::uint64_t{0x7ff8000000000123});
  const double negative_nan = std::bit_cast<double>(std::uint64_t{0xfff4000000000001});
  s.atoms[0].params[1].f = std::numeric_limits<double>::infinity();
  s.atoms[1].params[1].f = quiet_nan;
  s.atom_types[0].invariants[0].guard.instrs[1].imm.f = -std::numeric_limits<double>::infinity();
  s.atom_types[0].ports[0].stochastic->params[0].instrs[0].imm.f = negative_nan;
  const json data = ir::to_data(s);
  EXPECT_EQ(data["atoms"][0]["params"][1]["f"], "f64:7ff0000000000000");
  EXPECT_EQ(data["atoms"][1]["params"][1]["f"], "f64:7ff8000000000123");
  EXPECT_EQ(data["atom_types"][0]["invariants"][0]["guard"]["instrs"][1][5],
            "f64:fff0000000000000");
  // The text form has no NaN or infinity, so the data must survive dump and parse too.
  const ir::System back = ir::from_data(json::parse(data.dump()));
  EXPECT_EQ(back.atoms[0].params[1].f, std::numeric_limits<double>::infinity());
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back.atoms[1].params[1].f), 0x7ff8000000000123u);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(
                back.atom_types[0].ports[0].stochastic->params[0].instrs[0].imm.f),
            0xfff4000000000001u);
  const ir::System from_bytes = ir::from_bytes(ir::to_bytes(s));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(from_bytes.atoms[1].params[1].f), 0x7ff8000000000123u);
  EXPECT_EQ(ir::to_bytes(from_bytes), ir::to_bytes(s));
}

TEST(IrDataFields, DoublesRoundTripExactly) {
  ir::System s = sample_system();
  std::vector<double> values = {0.1,
                                1.0 / 3.0,
                                -0.0,
                                5e-324,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::lowest(),
                                std::numeric_limits<double>::min(),
                                std::nextafter(1.0, 2.0),
                                16777217.0,
                                3.0};
  ir::Code& code = s.atom_types[0].transitions[0].action;
  code.instrs.clear();
  for (double v : values) {
    ir::Instr in;
    in.op = Op::PushFloat;
    in.kind = ValueKind::Float;
    in.imm.f = v;
    code.instrs.push_back(in);
  }
  for (const ir::System& back : {ir::from_data(ir::to_data(s)), ir::from_bytes(ir::to_bytes(s)),
                                 ir::from_data(json::parse(ir::to_data(s).dump()))}) {
    const ir::Code& decoded = back.atom_types[0].transitions[0].action;
    ASSERT_EQ(decoded.instrs.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(decoded.instrs[i].imm.f),
                std::bit_cast<std::uint64_t>(values[i]))
          << values[i];
    }
  }
}

}  // namespace
}  // namespace smcbip::bipc
