// Instantiation at scale: a generated 10,000-atom chain lowers completely. Its speed is measured
// by bench/frontend_scaling.sh, not here: timings in unit tests fail on loaded or sanitized runs.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "lower_test_util.h"

namespace smcbip::bipc {
namespace {

/// The rendezvous chain of bench/gen_bip_models, with a data export and a priority per link so
/// that every kind of instance-level lookup is exercised at scale.
std::string chain_model(int atoms) {
  std::ostringstream out;
  out << "package chain\n"
         "  port type Link(int value)\n"
         "  connector type Rdv(Link giver, Link taker)\n"
         "    define giver taker\n"
         "    on giver taker provided (giver.value >= 0) down { taker.value = giver.value; }\n"
         "  end\n"
         "  atom type Node(int id)\n"
         "    export data int count\n"
         "    export port Link left(count), right(count)\n"
         "    place IDLE, BUSY\n"
         "    initial to IDLE do { count = id; }\n"
         "    on left from IDLE to BUSY do { count = count + 1; }\n"
         "    on right from BUSY to IDLE provided (count < 1000000)\n"
         "    on right from IDLE to IDLE\n"
         "  end\n"
         "  compound type Top()\n";
  for (int i = 0; i < atoms; ++i) out << "    component Node n" << i << "(" << i << ")\n";
  for (int i = 0; i + 1 < atoms; ++i) {
    out << "    connector Rdv c" << i << "(n" << i << ".right, n" << i + 1 << ".left)\n";
  }
  for (int i = 0; i + 2 < atoms; i += 2) {
    out << "    priority p" << i << " c" << i << ":* < c" << i + 1 << ":* provided (n" << i
        << ".count < n" << i + 1 << ".count)\n";
  }
  out << "  end\nend\n";
  return out.str();
}

TEST(LowerScaling, TenThousandAtomChainInstantiates) {
  constexpr int kAtoms = 10000;
  const std::string text = chain_model(kAtoms);
  auto lowered = std::make_unique<lower_test::Lowered>();
  const std::uint32_t file = lowered->model.files.add("chain.bip");
  std::unique_ptr<ast::Package> package = parse_package(text, file, lowered->diags);
  ASSERT_TRUE(package && !lowered->diags.has_errors()) << lowered->messages();
  lowered->model.main = package.get();
  lowered->model.packages.push_back(std::move(package));
  ASSERT_TRUE(check(lowered->model, lowered->diags)) << lowered->messages();
  std::optional<ast::ComponentDecl> root = parse_root("Top()", file, lowered->diags);
  ASSERT_TRUE(root && check_root(lowered->model, *root, lowered->diags)) << lowered->messages();

  std::optional<ir::System> system = instantiate(lowered->model, *root, lowered->diags);

  ASSERT_TRUE(system) << lowered->messages();
  EXPECT_EQ(system->atoms.size(), static_cast<std::size_t>(kAtoms));
  EXPECT_EQ(system->connectors.size(), static_cast<std::size_t>(kAtoms - 1));
  EXPECT_EQ(system->atom_types.size(), 1u);
  EXPECT_EQ(system->connector_types.size(), 1u);
  EXPECT_EQ(system->atoms.back().params.at(0).i, kAtoms - 1);
  EXPECT_EQ(system->compounds[0].priorities.size(), static_cast<std::size_t>((kAtoms - 1) / 2));
}

}  // namespace
}  // namespace smcbip::bipc
