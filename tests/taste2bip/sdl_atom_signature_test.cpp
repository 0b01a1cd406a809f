// The signature of a process inside an SDL system: signals from the environment are sporadic
// provided interfaces, signals to it sporadic required ones, their parameters `p1`, `p2`...
// typed by the SIGNAL declarations.
#include <gtest/gtest.h>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "taste2bip/translate/sdl_atom.h"

namespace smcbip::taste2bip {
namespace {

const char* const kSystem = R"(system s;
  signal go(T_Int, Pair), tick;
  signal report(T_Int);
  signal internal_only;
  channel c
    from env to b with go, tick;
    from b to env with report;
  endchannel;
  block b;
    signal local(T_Int);
    signalroute r
      from env to p with go, tick, local;
      from p to env with report;
      from p to q with internal_only;
    connect c and r;
    process p referenced;
    process q referenced;
  endblock;
endsystem;
)";

struct Read {
  asn1::DataView view;
  sdl::SdlFile file;
  bipc::Diagnostics diags;
};

void read(Read& r) {
  asn1::read_asn1(
      "M DEFINITIONS ::= BEGIN\nT-Int ::= INTEGER (0..9)\n"
      "Pair ::= SEQUENCE { a T-Int, b BOOLEAN }\nEND\n",
      0, r.view, r.diags);
  asn1::resolve(r.view, r.diags);
  r.file = sdl::read_sdl(kSystem, 1, r.diags);
  ASSERT_FALSE(r.diags.has_errors());
  ASSERT_EQ(r.file.systems.size(), 1u);
}

TEST(SdlAtomSignature, SignalsFromAndToTheEnvironment) {
  Read r;
  read(r);
  const auto signature = sdl_system_signature(r.file.systems[0], "p", r.view, r.diags);
  ASSERT_TRUE(signature);
  EXPECT_EQ(signature->name, "p");
  ASSERT_EQ(signature->provided.size(), 3u);
  EXPECT_EQ(signature->provided[0].name, "go");
  EXPECT_EQ(signature->provided[1].name, "tick");
  EXPECT_EQ(signature->provided[2].name, "local");  // declared in the block
  EXPECT_EQ(signature->provided[0].kind, InterfaceKind::Sporadic);
  EXPECT_EQ(signature->provided[0].data_names(false),
            (std::vector<std::string>{"go_p1", "go_p2_a", "go_p2_b"}));
  EXPECT_EQ(signature->provided[0].data_types(false),
            (std::vector<std::string>{"int", "int", "bool"}));
  ASSERT_EQ(signature->required.size(), 1u);
  EXPECT_EQ(signature->required[0].name, "report");
  EXPECT_FALSE(signature->required[0].synchronous());
}

TEST(SdlAtomSignature, UnknownProcessIsAnError) {
  Read r;
  read(r);
  EXPECT_FALSE(sdl_system_signature(r.file.systems[0], "nope", r.view, r.diags));
  EXPECT_TRUE(r.diags.has_errors());
}

}  // namespace
}  // namespace smcbip::taste2bip
