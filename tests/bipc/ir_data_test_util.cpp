// The sample System with every field set, model loading and the round-trip check.
#include "ir_data_test_util.h"

#include <algorithm>
#include <limits>

#include "bipc/ir/ir_data.h"
#include "bipc/ir/ir_json.h"
#include "bipc/ir/ir_text.h"

namespace smcbip::bipc::ir_data_test {

namespace {

using ir::Index;
using ir::kNone;
using ir::Op;
using ir::Scope;
using ir::ValueKind;

ir::Instr instr(Op op, ValueKind kind = ValueKind::Int, Scope scope = Scope::AtomData,
                Index index = 0, std::uint16_t arg = 0) {
  ir::Instr in;
  in.op = op;
  in.kind = kind;
  in.scope = scope;
  in.index = index;
  in.arg = arg;
  return in;
}

ir::Instr push_int(std::int64_t i) {
  ir::Instr in = instr(Op::PushInt);
  in.imm.i = i;
  return in;
}

ir::Instr push_float(double f) {
  ir::Instr in = instr(Op::PushFloat, ValueKind::Float);
  in.imm.f = f;
  return in;
}

ir::Instr push_bool(bool b) {
  ir::Instr in = instr(Op::PushBool, ValueKind::Bool);
  in.imm.b = b;
  return in;
}

ir::Code code(std::vector<ir::Instr> instrs) { return ir::Code{std::move(instrs), 0}; }

std::vector<ir::Annotation> annotations(const std::string& name, std::uint32_t line) {
  return {{name, {{"key", "value"}, {"flag", std::nullopt}}, {1, line, 7}}};
}

ir::DataType type(ValueKind kind, Index extern_type = kNone) { return {kind, extern_type}; }

void add_externs(ir::System& s) {
  s.strings = {"hello", "w\xc3\xb6rld", ""};
  s.extern_types = {{"pkg.Vec", "geo::Vec", {}}, {"pkg.Vec3", "geo::Vec3", {0}}};
  s.functions = {{"norm", false, type(ValueKind::Float), {type(ValueKind::Extern, 0)}, {true}},
                 {"==",
                  true,
                  type(ValueKind::Bool),
                  {type(ValueKind::Extern, 1), type(ValueKind::Extern, 1)},
                  {false, true}}};
  s.port_types = {{"pkg.P", {{"v", type(ValueKind::Int)}}},
                  {"pkg.Q", {}},
                  {"pkg.F", {{"u", type(ValueKind::Float)}}}};
}

ir::AtomType atom_type() {
  ir::AtomType t;
  t.name = "pkg.A";
  t.params = {{"n", type(ValueKind::Int)}, {"g", type(ValueKind::Float)}};
  t.data = {{"x", type(ValueKind::Int), true, code({push_int(5)})},
            {"vec", type(ValueKind::Extern, 0), false, code({})}};
  t.clocks = {{"c", ir::TimeUnit::Second}, {"h", ir::TimeUnit::Microsecond}};
  t.places = {"S", "T"};
  ir::Port p;
  p.name = "p";
  p.type = 0;
  p.data = {0};
  p.exported = true;
  p.is_extern = true;
  p.policy = ir::ExternPolicy::Ignore;
  p.backend_name = "ext_p";
  p.stochastic = ir::Stochastic{
      ir::Distribution::Gamma,
      1,
      {code({push_float(1.5)}), code({instr(Op::Load, ValueKind::Float, Scope::AtomParam, 1)})},
      "cdf.txt"};
  p.annotations = annotations("doc", 3);
  ir::Port q;
  q.name = "q";
  q.type = 1;
  t.ports = {p, q};
  t.interface = {{"p", 0, {0}}, {"both", 1, {0, 1}}};
  t.initial_places = {0};
  t.initial_action = code({instr(Op::Load, ValueKind::Int, Scope::AtomParam, 0),
                           instr(Op::Store, ValueKind::Int, Scope::AtomData, 0)});
  t.initial_resume = ir::Resume{code({push_bool(true)})};
  ir::Transition a;
  a.port = 0;
  a.from = {0};
  a.to = {1};
  a.guard = code({instr(Op::Load), push_int(std::numeric_limits<std::int64_t>::min()),
                  instr(Op::Lt, ValueKind::Int)});
  a.action = code({push_float(-0.0), instr(Op::Store, ValueKind::Float, Scope::Clock, 0)});
  a.urgency = ir::Urgency::Eager;
  a.resume = ir::Resume{code({push_bool(false)})};
  a.annotations = annotations("edge", 9);
  a.loc = {2, 12, 5};
  ir::Transition b;
  b.port = kNone;
  b.from = {1};
  b.to = {0, 1};
  b.guard = code({instr(Op::PushString, ValueKind::String, Scope::AtomData, 1),
                  instr(Op::PushString, ValueKind::String, Scope::AtomData, 0),
                  instr(Op::Eq, ValueKind::String),
                  instr(Op::JumpIfFalseKeep, ValueKind::Bool, Scope::AtomData, 5), push_bool(true),
                  instr(Op::Not, ValueKind::Bool)});
  ir::Instr call = instr(Op::Call, ValueKind::Float, Scope::AtomData, 0, 1);
  call.site = 1;
  b.action = code({push_float(2.0), instr(Op::StoreRate, ValueKind::Float, Scope::Clock, 1),
                   instr(Op::Load, ValueKind::Extern, Scope::AtomData, 1), call,
                   instr(Op::Pop, ValueKind::Void)});
  b.urgency = ir::Urgency::Delayable;
  t.transitions = {a, b};
  t.priorities = {{"pr", 0, kNone, code({push_bool(true)})}};
  t.invariants = {{"inv",
                   false,
                   {1},
                   code({instr(Op::Load, ValueKind::Float, Scope::Clock, 0), push_float(1e300),
                         instr(Op::Le, ValueKind::Float)})}};
  t.annotations = annotations("atom", 1);
  return t;
}

ir::ConnectorType rendezvous_type() {
  ir::ConnectorType t;
  t.name = "pkg.R";
  t.ports = {{"a", 0}, {"b", 0}};
  t.data = {{"z", type(ValueKind::Int), true, code({push_int(-3)})},
            {"w", type(ValueKind::Bool), false, code({push_bool(true)})}};
  t.export_name = "e";
  t.export_type = 0;
  t.export_data = {0};
  ir::DefineNode leaf_a{0, {}, true};
  ir::DefineNode leaf_b{1, {}, false};
  t.define = {leaf_a, ir::DefineNode{kNone, {leaf_b}, true}};
  t.interactions = {{{0, 1},
                     code({instr(Op::Load, ValueKind::Int, Scope::PortParam, 0, 0), push_int(0),
                           instr(Op::Gt, ValueKind::Int)}),
                     code({instr(Op::Load, ValueKind::Int, Scope::PortParam, 1, 0),
                           instr(Op::Store, ValueKind::Int, Scope::ConnectorData, 0)}),
                     code({instr(Op::Load, ValueKind::Int, Scope::ConnectorData, 0),
                           instr(Op::Store, ValueKind::Int, Scope::PortParam, 0, 0)}),
                     annotations("on", 20)}};
  t.resume = ir::ConnectorType::Resume::Async;
  t.annotations = annotations("connector", 18);
  return t;
}

void add_instances(ir::System& s) {
  ir::ConnectorType solo;
  solo.name = "pkg.Solo";
  solo.ports = {{"x", 0}};
  solo.define = {ir::DefineNode{0, {}, false}};
  ir::ConnectorType mono = solo;
  mono.name = "pkg.Mono";
  s.connector_types = {rendezvous_type(), solo, mono};

  s.atoms = {{"sub.a",
              0,
              1,
              {{ValueKind::Int, true, 3, 0.25, "three"}, {ValueKind::Float, false, -9, 2.5, ""}},
              annotations("instance", 30)},
             {"b", 0, 0, {{ValueKind::Int, false, -1, -0.0, "s"}, {}}, {}}};
  ir::ConnectorInstance inner;
  inner.path = "sub.r";
  inner.type = 0;
  inner.parent = 1;
  inner.bound = {{{ir::PortRef::Kind::Atom, 0, 0}}, {{ir::PortRef::Kind::Atom, 1, 0}}};
  inner.bound_names = {"a.p", "b.p"};
  inner.bound_through_compound = {false, true};
  inner.bound_by = 1;
  inner.bound_by_all = {1};
  inner.annotations = annotations("binding", 40);
  ir::ConnectorInstance top;
  top.path = "top";
  top.type = 1;
  top.parent = 0;
  top.bound = {{{ir::PortRef::Kind::Connector, 0, 0}}};
  top.bound_names = {"sub.out"};
  top.bound_through_compound = {true};
  s.connectors = {inner, top};

  ir::CompoundInstance root;
  root.path = "";
  root.type = "pkg.Top";
  root.parent = kNone;
  root.atoms = {1};
  root.compounds = {1, 2};
  root.connectors = {1};
  root.priorities = {{"prio",
                      {1, true, {}},
                      {kNone, false, {}},
                      code({instr(Op::Load, ValueKind::Int, Scope::InstanceData, 0, 0), push_int(2),
                            instr(Op::Gt, ValueKind::Int)})}};
  root.annotations = annotations("root", 50);
  ir::CompoundInstance sub;
  sub.path = "sub";
  sub.type = "pkg.Sub";
  sub.parent = 0;
  sub.atoms = {0};
  sub.connectors = {0};
  sub.priorities = {
      {"p2", {0, false, {{ir::PortRef::Kind::Atom, 0, 0}}}, {kNone, false, {}}, code({})}};
  sub.exported_ports = {{"out", {{ir::PortRef::Kind::Connector, 0, 0}}},
                        {"in", {{ir::PortRef::Kind::Atom, 0, 1}}}};
  sub.exported_data = {{"xx", {0, 0}}, {"yy", {0, 1}}};
  ir::CompoundInstance leaf;
  leaf.path = "sub.leaf";
  leaf.type = "pkg.Leaf";
  leaf.parent = 1;
  s.compounds = {root, sub, leaf};
}

}  // namespace

ir::System sample_system() {
  ir::System s;
  s.root_name = "Sys";
  s.root_type = "pkg.Top";
  add_externs(s);
  ir::AtomType idle;
  idle.name = "pkg.Idle";
  idle.params = {{"n", type(ValueKind::Int)}, {"m", type(ValueKind::Bool)}};
  idle.places = {"I"};
  idle.ports = {ir::Port{}};
  idle.ports[0].name = "tick";
  idle.ports[0].type = 1;
  idle.initial_places = {0};
  s.atom_types = {atom_type(), idle};
  add_instances(s);
  s.cpp_includes = {"geo.hpp", "stdio.h"};
  s.cpp_sources = {"src/geo.cpp"};
  s.cpp_include_dirs = {"src"};
  s.sites = {{0, 3, 9}, {1, 12, 5}};
  s.source_files = {"models/pkg.bip", "models/dep.bip"};
  ir::number_code(s);
  return s;
}

std::optional<ir::System> load_system(const std::filesystem::path& file, const std::string& root,
                                      const std::vector<std::string>& include_dirs,
                                      std::string* messages) {
  FrontendOptions options;
  options.file = file.string();
  options.include_dirs = include_dirs;
  options.root = root;
  FrontendResult result = run_frontend(options, true);
  if (messages != nullptr) *messages = result.diags.format(result.model.files);
  return std::move(result.system);
}

namespace {

/// The first difference between two JSON values, as a JSON patch operation (short).
std::string difference(const nlohmann::json& from, const nlohmann::json& to) {
  const nlohmann::json patch = nlohmann::json::diff(from, to);
  if (patch.empty()) return "(none)";
  std::string text = patch[0].dump();
  if (text.size() > 400) text = text.substr(0, 400) + "...";
  return text + " (" + std::to_string(patch.size()) + " operations)";
}

}  // namespace

void expect_round_trip(const ir::System& system, const std::string& label) {
  SCOPED_TRACE(label);
  const nlohmann::json data = ir::to_data(system);
  std::optional<ir::System> back;
  try {
    back = ir::from_data(data);
  } catch (const ir::IrDataError& e) {
    ADD_FAILURE() << "from_data rejected to_data's output: " << e.message;
    return;
  }
  // Compared as text: JSON values compare numbers by value, so 0.0 would equal -0.0.
  const nlohmann::json again = ir::to_data(*back);
  EXPECT_TRUE(again.dump() == data.dump())
      << "to_data differs after the round trip: " << difference(data, again);
  EXPECT_EQ(ir::to_json(*back).dump(), ir::to_json(system).dump());
  EXPECT_EQ(ir::to_text(*back), ir::to_text(system));

  const std::vector<std::uint8_t> bytes = ir::to_bytes(system);
  try {
    const ir::System from_bytes = ir::from_bytes(bytes);
    EXPECT_TRUE(ir::to_bytes(from_bytes) == bytes) << "to_bytes differs after from_bytes";
    EXPECT_EQ(ir::to_text(from_bytes), ir::to_text(system));
  } catch (const ir::IrDataError& e) {
    ADD_FAILURE() << "from_bytes rejected to_bytes's output: " << e.message;
  }
}

std::vector<std::filesystem::path> bip_files_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".bip") files.push_back(entry);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace smcbip::bipc::ir_data_test
