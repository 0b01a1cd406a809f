// The IR's stack code as Z3 terms: guards as formulas, actions as new values of an atom's data,
// by symbolic execution of every path of forward jumps.
#pragma once

#include <z3++.h>

#include <functional>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::fdir {

/// Where the code's loads find their values. `data` holds one term per data slot of the atom
/// (or is empty for connector code); `port_data` maps a connector's port parameter and the
/// parameter of its port type to a term (empty when the code is no connector code).
struct CodeFrame {
  std::vector<z3::expr> data;
  const std::vector<bipc::ir::Value>* params = nullptr;
  std::function<std::optional<z3::expr>(bipc::ir::Index, bipc::ir::Index)> port_data;
};

/// Translates code over a context. What Z3 cannot state exactly over integers and booleans
/// (floats, clocks, strings, calls of extern functions, bit operations, connector data) becomes
/// a fresh unknown constant, listed in `fresh()`, so that every translation over-approximates
/// the code's behaviour: a guard may then be true or false, a store writes any value.
/// Integer results outside the 64 bits the engines wrap around on are unknown.
class CodeEncoder {
 public:
  explicit CodeEncoder(z3::context& context) : context_(context), fresh_(context) {}

  /// The value of an expression (a guard: a formula; an empty code: true).
  z3::expr expression(const bipc::ir::Code& code, const CodeFrame& frame);
  /// Runs a statement block: `frame.data` receives the data's values after it.
  void statement(const bipc::ir::Code& code, CodeFrame& frame);
  /// A fresh unknown constant of the kind's sort (Bool, Int, Real otherwise), listed in fresh().
  z3::expr unknown(bipc::ir::ValueKind kind);
  /// The unknown constants made since the last clear_fresh().
  const z3::expr_vector& fresh() const { return fresh_; }
  void clear_fresh() { fresh_ = z3::expr_vector(context_); }
  z3::context& context() { return context_; }

 private:
  struct Path;
  /// Every path through the code; nullopt when it cannot be followed (backward jump, too many
  /// paths).
  std::optional<std::vector<Path>> paths(const bipc::ir::Code& code, const CodeFrame& frame);
  void step(const bipc::ir::Instr& in, const CodeFrame& frame, Path& path);
  z3::expr load(const bipc::ir::Instr& in, const CodeFrame& frame, const Path& path);
  void store(const bipc::ir::Instr& in, Path& path);
  z3::expr binary(const bipc::ir::Instr& in, const z3::expr& a, const z3::expr& b);
  z3::expr arithmetic(bipc::ir::Op op, const z3::expr& a, const z3::expr& b);
  z3::expr in_range(const z3::expr& exact);

  z3::context& context_;
  z3::expr_vector fresh_;
  unsigned counter_ = 0;
};

/// `e` (an integer term) lies in the engines' 64-bit range; true for other sorts.
z3::expr int64_bounds(const z3::expr& e);

/// Whether the connector code `down` stores into the data of port parameter `param` (the data
/// transfer the encodings do not follow, havocking what it writes).
bool writes_port(const bipc::ir::Code& down, bipc::ir::Index param);

/// The constant value as a term (Bool or Int; other kinds are unknown to `encoder`).
z3::expr value_term(CodeEncoder& encoder, const bipc::ir::Value& value);

}  // namespace smcbip::fdir
