// The flat step path over an interpreted model.
#include "engines/semantics/interpreted_steps.h"

#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_steps.h"
#include "engines/semantics/flat_steps.h"

namespace smcbip::engines {

namespace {

/// The interpreter with every atom type's steps answered by interpretation, final so that the
/// flat step path binds its calls statically.
class InterpretedAtoms final : public ModelCode {
 public:
  InterpretedAtoms(CodeEvaluator& eval, const bipc::ir::System& system, const Layout& layout)
      : eval_(eval), system_(system), layout_(layout) {}

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
    return interpreted_offers(system_, layout_, type, marking, frame, eval_, offers);
  }
  bipc::ir::Index atom_internal(bipc::ir::Index type, const std::uint8_t* marking,
                                const Frame& frame) override {
    return interpreted_internal(system_, layout_, type, marking, frame, eval_);
  }
  bool atom_fire(bipc::ir::Index type, bipc::ir::Index transition, std::uint8_t* marking,
                 const Frame& frame) override {
    return interpreted_fire(system_.atom_types[type].transitions[transition], marking, frame,
                            eval_);
  }

 private:
  CodeEvaluator& eval_;
  const bipc::ir::System& system_;
  const Layout& layout_;
};

/// The flat steps with the interpreter they call.
class InterpretedSteps final : public CompiledSteps {
 public:
  InterpretedSteps(CodeEvaluator& eval, const bipc::ir::System& system, const Layout& layout)
      : atoms_(eval, system, layout), steps_(make_flat_steps(atoms_, system, layout)) {}
  bool covered() const { return steps_ != nullptr; }
  bool begin(const Run& run) override { return steps_->begin(run); }
  Outcome step(bool at_limit, StepInfo& info) override { return steps_->step(at_limit, info); }

 private:
  InterpretedAtoms atoms_;
  std::unique_ptr<CompiledSteps> steps_;
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
