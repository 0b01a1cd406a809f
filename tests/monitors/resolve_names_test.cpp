// Names of properties bound to a model: models/channel.bip and a small model with an ambiguous
// member and exported data.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "channel_model.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"

namespace smcbip::monitors {
namespace {

/// The diagnostics of resolving `text` against `system` (empty when it resolves), and the file.
std::string resolve(const std::string& text, const bipc::ir::System& system,
                    PropertyFile* out = nullptr) {
  ParsedProperties parsed = parse_properties(text, "p.mtl");
  if (!parsed.ok()) return "parse: " + parsed.diagnostics.format(parsed.sources);
  resolve_names(parsed.file, system, parsed.diagnostics);
  if (out != nullptr) *out = std::move(parsed.file);
  return parsed.diagnostics.format(parsed.sources);
}

TEST(ResolveNames, BindsDataPlacesClocksAndConnectors) {
  PropertyFile file;
  ASSERT_EQ(resolve("const k = 2\n"
                    "P=? [ F[0,100] (Channel.id_channel > k && ROOT.Receiver.c2) ]\n"
                    "P=? [ G[0,50] (Channel.x < 14 || fired(loss)) ]\n"
                    "P=? [ F[0,50] fired(Receiver.process) ]\n",
                    channel(), &file),
            "");
  const bipc::ir::System& s = channel();
  const Formula& first = *file.queries[0].formula->operands[0];  // F's operand: the &&
  const Expr& greater = *first.operands[0]->atom;
  const Reference& id = greater.operands[0]->reference;
  EXPECT_EQ(id.kind, Reference::Kind::Data);
  EXPECT_EQ(s.atoms[id.atom].path, "Channel");
  EXPECT_EQ(s.atom_types[s.atoms[id.atom].type].data[id.index].name, "id_channel");
  EXPECT_EQ(greater.operands[1]->reference.kind, Reference::Kind::Constant);
  const Reference& c2 = first.operands[1]->atom->reference;
  EXPECT_EQ(c2.kind, Reference::Kind::Place);
  EXPECT_EQ(s.atom_types[s.atoms[c2.atom].type].places[c2.index], "c2");

  const Formula& second = *file.queries[1].formula->operands[0];  // G's operand: the ||
  EXPECT_EQ(second.operands[0]->atom->operands[0]->reference.kind, Reference::Kind::Clock);
  const Reference& loss = second.operands[1]->atom->reference;
  EXPECT_EQ(loss.kind, Reference::Kind::Connector);
  EXPECT_EQ(s.connectors[loss.index].path, "loss");
  EXPECT_EQ(file.queries[2].formula->operands[0]->atom->reference.kind,
            Reference::Kind::InternalPort);
}

TEST(ResolveNames, ReportsUnknownNamesWhereTheyAre) {
  EXPECT_EQ(resolve("P=? [ F[0,10] Chanel.lost > 0 ]", channel()),
            "p.mtl:1:15: error: unknown atom 'Chanel' in 'Chanel.lost'\n");
  EXPECT_EQ(resolve("P=? [ F[0,10] Channel.lots > 0 ]", channel()),
            "p.mtl:1:15: error: atom 'Channel' (channel.Channel) has no data, place or clock "
            "'lots'\n");
  EXPECT_EQ(resolve("P=? [ F[0,10] lost > 0 ]", channel()),
            "p.mtl:1:15: error: unknown name 'lost': expected atom.data, atom.place or "
            "atom.clock, or a declared constant or parameter\n");
  EXPECT_EQ(resolve("P=? [ F[0,10] fired(lost) ]", channel()),
            "p.mtl:1:15: error: fired(lost): no connector or atom port of that name\n");
}

TEST(ResolveNames, TypesPredicates) {
  EXPECT_EQ(resolve("P=? [ F[0,10] Channel.lost ]", channel()),
            "p.mtl:1:15: error: an atomic predicate must be a condition, but 'Channel.lost' is "
            "a number\n");
  EXPECT_EQ(resolve("P=? [ F[0,10] Receiver.c2 + 1 > 0 ]", channel()),
            "p.mtl:1:15: error: 'Receiver.c2' is a condition where 'Receiver.c2 + 1' needs a "
            "number\n");
  EXPECT_EQ(resolve("P=? [ F[0,10] Receiver.c2 == 1 ]", channel()),
            "p.mtl:1:27: error: 'Receiver.c2 == 1' compares a condition with a number\n");
  EXPECT_EQ(resolve("E[<=100; 10](max: Receiver.c2)", channel()),
            "p.mtl:1:19: error: the observed expression must be a number, but 'Receiver.c2' is "
            "a condition\n");
  EXPECT_EQ(resolve("E[<=100; 10](max: Sender.sent - Sender.acked)", channel()), "");
}

TEST(ResolveNames, RefusesAPlaceThatIsAlsoAVariableAndReadsExportedData) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(
      "package amb\n"
      "  port type Sig()\n"
      "  connector type One(Sig p)\n    define p\n  end\n"
      "  atom type A()\n"
      "    export data int busy\n"
      "    export port Sig go()\n"
      "    place busy, idle\n"
      "    initial to idle do { busy = 0; }\n"
      "    on go from idle to busy\n"
      "  end\n"
      "  compound type Node()\n"
      "    component A a()\n"
      "    export port a.go as go\n"
      "    export data a.busy as load\n"
      "  end\n"
      "  compound type Top()\n"
      "    component Node n()\n"
      "    connector One c(n.go)\n"
      "  end\n"
      "end\n",
      "Top()");
  ASSERT_TRUE(system);
  EXPECT_EQ(resolve("P=? [ F{1} n.a.busy ]", *system),
            "p.mtl:1:12: error: 'n.a.busy' is ambiguous: 'busy' is both a place and a variable "
            "of atom 'n.a'\n");
  EXPECT_EQ(resolve("P=? [ F{1} n.load > 0 ]", *system), "");
  EXPECT_EQ(resolve("P=? [ F{1} n.weight > 0 ]", *system),
            "p.mtl:1:12: error: compound 'n' exports no data 'weight'\n");
  // The model has no clocks: time measures nothing it shows.
  EXPECT_EQ(resolve("P=? [ F[0,1] n.load > 0 ]", *system),
            "p.mtl:1:11: error: the model has no clocks, so a time bound measures nothing it "
            "shows: bound by steps instead (F{k} phi or F[#<=k] phi, Pr[#<=K](...))\n");
  EXPECT_NE(resolve("P=? [ F{3} time > 2 ]", *system).find("'time' measures nothing"),
            std::string::npos);
}

}  // namespace
}  // namespace smcbip::monitors
