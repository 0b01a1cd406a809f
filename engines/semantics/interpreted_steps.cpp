// The flat step path over an interpreted model.
#include "engines/semantics/interpreted_steps.h"

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/simple_action.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_steps.h"
#include "engines/semantics/flat_steps.h"
#include "engines/semantics/offer_memo.h"

namespace smcbip::engines {

namespace {

/// The interpreter with every atom type's steps answered by interpretation, final so that the
/// flat step path binds its calls statically.
class InterpretedAtoms final : public ModelCode {
 public:
  InterpretedAtoms(CodeEvaluator& eval, const bipc::ir::System& system, const Layout& layout)
      : eval_(eval), system_(system), layout_(layout), memo_(system, layout) {
    for (const bipc::ir::AtomType& type : system.atom_types) {
      first_action_.push_back(static_cast<std::uint32_t>(actions_.size()));
      for (const bipc::ir::Transition& transition : type.transitions) {
        Action action;
        if (auto simple = bipc::ir::simple_action(transition.action)) {
          action.first = static_cast<std::uint32_t>(assignments_.size());
          assignments_.insert(assignments_.end(), simple->begin(), simple->end());
          action.end = static_cast<std::uint32_t>(assignments_.size());
        }
        actions_.push_back(action);
      }
    }
  }

  Val evaluate(const bipc::ir::Code& code, const Frame& frame) override {
    return eval_.evaluate(code, frame);
  }
  void execute(const bipc::ir::Code& code, const Frame& frame) override {
    eval_.execute(code, frame);
  }
  Interval holds_when(const bipc::ir::Code& code, const Frame& frame) override {
    return eval_.holds_when(code, frame);
  }
  bool compiles_atom_type(bipc::ir::Index /*type*/) const override { return true; }
  bipc::ir::Index atom_offers(bipc::ir::Index type, const std::uint8_t* marking, const Frame& frame,
                              std::optional<AtomPortValue>* offers) override {
    if (!memo_.keeps(type)) {
      return interpreted_offers(system_, layout_, type, marking, frame, eval_, offers);
    }
    bipc::ir::Index result = bipc::ir::kNone;
    if (memo_.find(type, marking, frame, offers, result)) return result;
    result = interpreted_offers(system_, layout_, type, marking, frame, eval_, offers);
    memo_.remember(type, marking, frame, offers, result);
    return result;
  }
  bipc::ir::Index atom_internal(bipc::ir::Index type, const std::uint8_t* marking,
                                const Frame& frame) override {
    return interpreted_internal(system_, layout_, type, marking, frame, eval_);
  }
  bool atom_fire(bipc::ir::Index type, bipc::ir::Index transition, std::uint8_t* marking,
                 const Frame& frame) override {
    const bipc::ir::Transition& tr = system_.atom_types[type].transitions[transition];
    const Action& action = actions_[first_action_[type] + transition];
    if (action.first == kInterpreted) return interpreted_fire(tr, marking, frame, eval_);
    if (!move_tokens(tr, marking)) return false;
    run_simple_action(assignments_.data() + action.first, assignments_.data() + action.end, frame);
    return true;
  }

 private:
  /// A transition's action: its assignments in assignments_, or kInterpreted.
  static constexpr std::uint32_t kInterpreted = 0xFFFFFFFFu;
  struct Action {
    std::uint32_t first = kInterpreted, end = 0;
  };

  CodeEvaluator& eval_;
  const bipc::ir::System& system_;
  const Layout& layout_;
  OfferMemo memo_;
  // Per atom type its first transition's entry in actions_; the simple actions' assignments.
  std::vector<std::uint32_t> first_action_;
  std::vector<Action> actions_;
  std::vector<bipc::ir::SimpleAssignment> assignments_;
};

/// The flat steps with the interpreter they call.
class InterpretedSteps final : public CompiledSteps {
 public:
  InterpretedSteps(CodeEvaluator& eval, const bipc::ir::System& system, const Layout& layout)
      : atoms_(eval, system, layout) {
    if (std::optional<FlatTables> tables = flat_tables(system, layout, atoms_)) {
      steps_.emplace(atoms_, system, layout, std::move(*tables));
    }
  }
  bool covered() const { return steps_.has_value(); }
  bool begin(const Run& run) override { return steps_->begin(run); }
  Outcome step(bool at_limit, StepInfo& info) override { return steps_->step(at_limit, info); }
  bool step_kept_state() const override { return steps_->step_kept_state(); }
  void check_kept_state() override { steps_->check_kept_state(); }

 private:
  InterpretedAtoms atoms_;
  // Held by its final type: the forwarding calls bind statically.
  std::optional<FlatSteps<InterpretedAtoms>> steps_;
};

}  // namespace

std::unique_ptr<CompiledSteps> make_interpreted_steps(ModelCode& code,
                                                      const bipc::ir::System& system,
                                                      const Layout& layout) {
  auto* eval = dynamic_cast<CodeEvaluator*>(&code);
  if (eval == nullptr) return nullptr;
  auto steps = std::make_unique<InterpretedSteps>(*eval, system, layout);
  if (!steps->covered()) return nullptr;
  return steps;
}

}  // namespace smcbip::engines
