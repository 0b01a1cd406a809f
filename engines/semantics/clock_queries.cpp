// What the stochastic date planner asks of a running atom: the evaluated parameters of a port's
// @stochastic annotation.
#include <cmath>
#include <optional>

#include "engines/semantics/runtime.h"

namespace smcbip::engines {

std::optional<double> number_param(const bipc::ir::Code& code) {
  using bipc::ir::Op;
  const std::vector<bipc::ir::Instr>& in = code.instrs;
  if (in.size() == 1 && in[0].op == Op::PushFloat) return in[0].imm.f;
  if (in.size() == 2 && in[0].op == Op::PushInt && in[1].op == Op::IntToFloat) {
    return static_cast<double>(in[0].imm.i);
  }
  return std::nullopt;
}

void Runtime::stochastic_params(Index atom, Index port, std::vector<double>& out) {
  const auto& stochastic = system_.atom_types[system_.atoms[atom].type].ports[port].stochastic;
  out.clear();
  if (!stochastic) return;
  std::optional<Frame> f;
  for (const bipc::ir::Code& code : stochastic->params) {
    if (const std::optional<double> number = number_param(code)) {
      out.push_back(*number);
      continue;
    }
    if (!f) f = atoms_.frame(atom);
    out.push_back(eval_.evaluate(code, *f).f);
  }
}

}  // namespace smcbip::engines
