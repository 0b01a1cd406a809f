// The tables generated code exports for the engines' compiled step path (ModelCode::
// compiled_atoms) agree with its interface: an atom type's fire_and_offer with fire, internal
// and offers called one by one as the flat step path called them, and the connectors' code by
// Code::id with evaluate and execute.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "generated_models.h"
#include "random_models.h"
#include "run_trace.h"
#include "tests/engines/temp_model.h"

namespace smcbip::tests {
namespace {

using bipc::ir::Index;
using engines::AtomPortValue;
using engines::Frame;
using engines::ModelCode;
using engines::Val;

/// An atom of one type in a state of the test's making: its data as its initial values and
/// action leave them, its clocks started at 0 and read at 2.5 units, any marking.
struct AtomState {
  std::vector<std::uint8_t> marking;
  std::vector<Val> data, params;
  std::vector<engines::ClockState> clocks;
  std::vector<engines::TimeValue> units;
  std::vector<std::optional<AtomPortValue>> offers;

  Frame frame() {
    Frame f;
    f.atom_data = data.data();
    f.atom_params = params.data();
    f.clocks = clocks.empty() ? nullptr : clocks.data();
    f.clock_units = units.data();
    f.now = 2'500'000;
    return f;
  }
};

AtomState initial_state(const bipc::ir::AtomType& type, ModelCode& code) {
  AtomState state;
  state.marking.assign(type.places.size(), 0);
  state.data.assign(type.data.size(), Val{});
  state.params.assign(type.params.size(), Val{});
  state.clocks.assign(type.clocks.size(), engines::ClockState{});
  state.units.assign(type.clocks.size() + 1, 1'000'000);
  state.offers.assign(type.ports.size(), std::nullopt);
  const Frame f = state.frame();
  for (std::size_t d = 0; d < type.data.size(); ++d) {
    if (!type.data[d].initial_value.empty()) {
      state.data[d] = code.evaluate(type.data[d].initial_value, f);
    }
  }
  code.execute(type.initial_action, f);
  return state;
}

/// What a firing left: its result or fault, then the atom's marking, data and offers (offers
/// only when it succeeded: they are partial otherwise).
std::string outcome(const AtomState& state, const std::string& result) {
  std::ostringstream out;
  out << result << " marking";
  for (std::uint8_t m : state.marking) out << ' ' << int(m);
  out << " data";
  for (const Val& v : state.data) out << ' ' << v.i;
  if (result != "true") return out.str();
  out << " offers";
  for (const std::optional<AtomPortValue>& offer : state.offers) {
    if (!offer) {
      out << " -";
      continue;
    }
    const engines::Interval& w = offer->constraint.interval;
    out << " t" << offer->transition << (w.left_open ? "(" : "[") << w.left << ',' << w.right
        << (w.right_open ? ")" : "]") << int(offer->constraint.urgency);
  }
  return out.str();
}

/// Runs `fire` on the state, its fault as its result.
template <class Fire>
std::string fired(AtomState& state, Fire fire) {
  std::string result;
  try {
    result = fire(state.frame()) ? "true" : "false";
  } catch (const engines::CodeFault& fault) {
    result = "fault: " + fault.message;
  }
  return outcome(state, result);
}

/// Fires every transition of every atom type from every marking (of at most 8 places; else
/// those of one place) both ways; the number of firings compared.
std::size_t compare_fire_and_offer(const bipc::ir::System& system, ModelCode& code) {
  const engines::CompiledAtoms atoms = code.compiled_atoms();
  EXPECT_EQ(atoms.types.size(), system.atom_types.size());
  std::size_t compared = 0;
  for (Index k = 0; k < atoms.types.size(); ++k) {
    const bipc::ir::AtomType& type = system.atom_types[k];
    const engines::CompiledAtomSteps& steps = atoms.types[k];
    const AtomState initial = initial_state(type, code);
    const std::size_t places = type.places.size();
    const std::size_t markings = places <= 8 ? std::size_t{1} << places : places;
    for (std::size_t bits = 0; bits < markings; ++bits) {
      AtomState from = initial;
      for (std::size_t p = 0; p < places; ++p) {
        from.marking[p] = places <= 8 ? (bits >> p) & 1 : p == bits;
      }
      for (Index t = 0; t < type.transitions.size(); ++t) {
        AtomState one = from, parts = from;
        const std::string in_one = fired(one, [&](const Frame& f) {
          return steps.fire_and_offer(atoms.context, t, one.marking.data(), f, one.offers.data());
        });
        const std::string in_parts = fired(parts, [&](const Frame& f) {
          std::uint8_t* m = parts.marking.data();
          if (!steps.fire(atoms.context, t, m, f)) return false;
          for (;;) {
            const Index next = steps.internal(atoms.context, m, f);
            if (next == bipc::ir::kNone) break;
            if (next == ModelCode::kSeveralTransitions || !steps.fire(atoms.context, next, m, f)) {
              return false;
            }
          }
          for (auto& offer : parts.offers) offer.reset();
          return steps.offers(atoms.context, m, f, parts.offers.data()) == bipc::ir::kNone;
        });
        EXPECT_EQ(in_one, in_parts) << type.name << " transition " << t << " marking " << bits;
        ++compared;
      }
    }
  }
  return compared;
}

/// The code table holds the connectors' non-empty guards (evaluate) and `up` and `down`
/// (execute), and nothing else; the number of entries checked.
std::size_t check_code_table(const bipc::ir::System& system, ModelCode& code) {
  const engines::CompiledAtoms atoms = code.compiled_atoms();
  std::vector<int> expected(system.code_count, 0);  // 1 evaluate, 2 execute
  for (const bipc::ir::ConnectorType& type : system.connector_types) {
    for (const bipc::ir::InteractionCode& interaction : type.interactions) {
      if (!interaction.guard.empty()) expected[interaction.guard.id] = 1;
      if (!interaction.up.empty()) expected[interaction.up.id] = 2;
      if (!interaction.down.empty()) expected[interaction.down.id] = 2;
    }
  }
  EXPECT_LE(atoms.code.size(), expected.size());
  std::size_t entries = 0;
  for (std::size_t id = 0; id < expected.size(); ++id) {
    const engines::CompiledCode entry =
        id < atoms.code.size() ? atoms.code[id] : engines::CompiledCode{};
    EXPECT_EQ(entry.evaluate != nullptr, expected[id] == 1) << "code " << id;
    EXPECT_EQ(entry.execute != nullptr, expected[id] == 2) << "code " << id;
    entries += expected[id] != 0 ? 1 : 0;
  }
  return entries;
}

/// A connector's slots for its code: its data, and kSlots per port, all 0 but the first port's
/// first (so that a guard `a.x >= 0` or a `down` copying it shows).
struct ConnectorState {
  static constexpr std::size_t kSlots = 8;  // more than any port type of the models has
  std::vector<Val> data;
  mutable std::vector<Val> ports;

  static Val* port_slot(const void* context, Index port, std::uint16_t arg) {
    return &static_cast<const ConnectorState*>(context)->ports[port * kSlots + arg];
  }
  Frame frame() {
    Frame f;
    f.connector_data = data.data();
    f.port_slot = &port_slot;
    f.port_context = this;
    return f;
  }
};

// Each connector code entry computes what evaluate and execute compute for that Code, on the
// same slots: its value, and the slots it leaves.
void compare_connector_code(const bipc::ir::System& system, ModelCode& code) {
  const engines::CompiledAtoms atoms = code.compiled_atoms();
  for (const bipc::ir::PortType& type : system.port_types) {
    ASSERT_LE(type.params.size(), ConnectorState::kSlots) << type.name;
  }
  for (const bipc::ir::ConnectorType& type : system.connector_types) {
    for (const bipc::ir::InteractionCode& interaction : type.interactions) {
      for (const bipc::ir::Code* c : {&interaction.guard, &interaction.up, &interaction.down}) {
        if (c->empty()) continue;
        ConnectorState initial{std::vector<Val>(type.data.size(), Val{}),
                               std::vector<Val>(type.ports.size() * ConnectorState::kSlots)};
        initial.ports[0].i = 7;
        ConnectorState table = initial, interface = initial;
        const engines::CompiledCode& entry = atoms.code[c->id];
        if (entry.evaluate != nullptr) {
          EXPECT_EQ(entry.evaluate(atoms.context, table.frame()).b,
                    code.evaluate(*c, interface.frame()).b);
        } else {
          entry.execute(atoms.context, table.frame());
          code.execute(*c, interface.frame());
        }
        for (std::size_t s = 0; s < initial.ports.size(); ++s) {
          EXPECT_EQ(table.ports[s].i, interface.ports[s].i) << type.name << " slot " << s;
        }
        for (std::size_t s = 0; s < initial.data.size(); ++s) {
          EXPECT_EQ(table.data[s].i, interface.data[s].i) << type.name << " datum " << s;
        }
      }
    }
  }
}

// The models of models/ the compiled step path covers, and the random ones.
TEST(CompiledTables, FireAndOfferIsTheThreeInTurn) {
  std::size_t models = 0, compared = 0;
  const auto check = [&](const bipc::ir::System& system,
                         const engines::CompiledModel::CodeFactory& make_code) {
    ASSERT_TRUE(
        with_generated_code(system, make_code, [&](const engines::Layout&, ModelCode& code) {
          compared += compare_fire_and_offer(system, code);
        }));
    ++models;
  };
  for (const GeneratedModel& generated : generated_models()) {
    if (!has_compiled_steps(generated.system(), generated.make_code)) continue;
    check(generated.system(), generated.make_code);
  }
  for (const GeneratedRandomModel& generated : generated_random_models()) {
    const std::optional<bipc::ir::System> system = load_model(generated.file, "Root()");
    ASSERT_TRUE(system) << generated.file;
    check(*system, generated.make_code);
  }
  EXPECT_EQ(models, 10u + 42u);
  EXPECT_GT(compared, 1000u);
}

TEST(CompiledTables, HoldTheConnectorsCode) {
  std::size_t entries = 0;
  for (const GeneratedModel& generated : generated_models()) {
    if (!has_compiled_steps(generated.system(), generated.make_code)) continue;
    ASSERT_TRUE(with_generated_code(generated.system(), generated.make_code,
                                    [&](const engines::Layout&, ModelCode& code) {
                                      entries += check_code_table(generated.system(), code);
                                      compare_connector_code(generated.system(), code);
                                    }));
  }
  // channel's Transfer `down`, the chain's guard and `down`, and more.
  EXPECT_GE(entries, 3u);
}

}  // namespace
}  // namespace smcbip::tests
