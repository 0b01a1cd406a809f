// Property formulas as Z3 terms and as values of engine states.
#include "fdir/prove/property_encoding.h"

#include <cmath>

#include "engines/api/run_observer.h"
#include "fdir/errors.h"
#include "monitors/run/run_monitor.h"

namespace smcbip::fdir {

namespace {

using monitors::Expr;
using monitors::Formula;
using monitors::Reference;

[[noreturn]] void unsupported(const monitors::Location& at, const std::string& what) {
  throw UnsupportedModel(what + " is not supported by prove", at, true);
}

class ExprEncoder {
 public:
  ExprEncoder(const StateEncoding& state, const monitors::Bindings& constants,
              const z3::expr& deadlock)
      : state_(state), constants_(constants), deadlock_(deadlock) {}

  z3::expr term(const Expr& e) {
    z3::context& c = state_.context();
    switch (e.kind) {
      case Expr::Kind::Number:
        if (e.value.is_name()) return constant(e);
        if (e.value.integral) return c.int_val(static_cast<int64_t>(e.value.number));
        return c.real_val(e.value.text.c_str());
      case Expr::Kind::Bool:
        return c.bool_val(e.boolean);
      case Expr::Kind::Name:
        return name(e);
      case Expr::Kind::Negate:
        return -term(*e.operands[0]);
      case Expr::Kind::Call:
        return call(e);
      case Expr::Kind::Fired:
        unsupported(e.at, "fired()");
      case Expr::Kind::Modulo:
        unsupported(e.at, "%");
      default:
        return binary(e);
    }
  }

 private:
  z3::expr constant(const Expr& e) {
    const std::string& n = e.value.is_name() ? e.value.name : e.path;
    const auto found = constants_.find(n);
    if (found == constants_.end()) unsupported(e.at, "the parameter '" + n + "'");
    const double v = found->second;
    if (v == std::floor(v) && std::abs(v) < 1e15) {
      return state_.context().int_val(static_cast<int64_t>(v));
    }
    return state_.context().real_val(std::to_string(v).c_str());
  }

  z3::expr name(const Expr& e) {
    const Reference& r = e.reference;
    switch (r.kind) {
      case Reference::Kind::Place:
        return state_.place(r.atom, r.index);
      case Reference::Kind::Data: {
        const z3::expr& d = state_.data(r.atom)[r.index];
        if (!d.is_int() && !d.is_bool()) unsupported(e.at, "data other than int and bool");
        return d;
      }
      case Reference::Kind::Constant:
        return constant(e);
      case Reference::Kind::Deadlock:
        return deadlock_;
      case Reference::Kind::Clock:
        unsupported(e.at, "a clock");
      default:
        unsupported(e.at, "'" + e.path + "'");
    }
  }

  static void same_sort(z3::expr& a, z3::expr& b) {
    if (a.is_int() && b.is_real()) a = z3::to_real(a);
    if (a.is_real() && b.is_int()) b = z3::to_real(b);
  }

  z3::expr call(const Expr& e) {
    z3::expr a = term(*e.operands[0]);
    if (e.path == "abs") return z3::ite(a >= 0, a, -a);
    z3::expr b = term(*e.operands.at(1));
    same_sort(a, b);
    if (e.path == "min") return z3::ite(a <= b, a, b);
    if (e.path == "max") return z3::ite(a >= b, a, b);
    unsupported(e.at, "the function " + e.path);
  }

  z3::expr binary(const Expr& e) {
    z3::expr a = term(*e.operands[0]);
    z3::expr b = term(*e.operands[1]);
    if (a.is_bool() != b.is_bool()) unsupported(e.at, "comparing a condition with a number");
    same_sort(a, b);
    switch (e.kind) {
      case Expr::Kind::Add:
        return a + b;
      case Expr::Kind::Subtract:
        return a - b;
      case Expr::Kind::Multiply:
        return a * b;
      case Expr::Kind::Divide:  // the monitors divide numbers as reals
        return (a.is_int() ? z3::to_real(a) : a) / (b.is_int() ? z3::to_real(b) : b);
      case Expr::Kind::Less:
        return a < b;
      case Expr::Kind::LessEqual:
        return a <= b;
      case Expr::Kind::Greater:
        return a > b;
      case Expr::Kind::GreaterEqual:
        return a >= b;
      case Expr::Kind::Equal:
        return a == b;
      case Expr::Kind::NotEqual:
        return a != b;
      default:
        unsupported(e.at, "this operator");
    }
  }

  const StateEncoding& state_;
  const monitors::Bindings& constants_;
  const z3::expr& deadlock_;
};

z3::expr formula_term(const Formula& f, ExprEncoder& encoder, z3::context& c) {
  auto operand = [&](std::size_t k) { return formula_term(*f.operands[k], encoder, c); };
  switch (f.kind) {
    case Formula::Kind::True:
      return c.bool_val(true);
    case Formula::Kind::False:
      return c.bool_val(false);
    case Formula::Kind::Atom: {
      z3::expr e = encoder.term(*f.atom);
      if (!e.is_bool()) unsupported(f.at, "a number as a condition");
      return e;
    }
    case Formula::Kind::Not:
      return !operand(0);
    case Formula::Kind::And:
      return operand(0) && operand(1);
    case Formula::Kind::Or:
      return operand(0) || operand(1);
    case Formula::Kind::Implies:
      return z3::implies(operand(0), operand(1));
    case Formula::Kind::Iff:
      return operand(0) == operand(1);
    default:
      unsupported(f.at, "a temporal operator under A[] or E<>");
  }
}

bool formula_value(const Formula& f, const monitors::StateView& state,
                   const monitors::Bindings& constants) {
  auto operand = [&](std::size_t k) { return formula_value(*f.operands[k], state, constants); };
  switch (f.kind) {
    case Formula::Kind::True:
      return true;
    case Formula::Kind::False:
      return false;
    case Formula::Kind::Atom:
      return monitors::evaluate(*f.atom, state, constants) != 0;
    case Formula::Kind::Not:
      return !operand(0);
    case Formula::Kind::And:
      return operand(0) && operand(1);
    case Formula::Kind::Or:
      return operand(0) || operand(1);
    case Formula::Kind::Implies:
      return !operand(0) || operand(1);
    case Formula::Kind::Iff:
      return operand(0) == operand(1);
    default:
      unsupported(f.at, "a temporal operator under A[] or E<>");
  }
}

}  // namespace

z3::expr encode_formula(const Formula& formula, const StateEncoding& state,
                        const monitors::Bindings& constants, const z3::expr& deadlock_states) {
  ExprEncoder encoder(state, constants, deadlock_states);
  return formula_term(formula, encoder, state.context());
}

bool holds_in(const Formula& formula, const engines::Runtime& runtime,
              const engines::StringPool& strings, const monitors::Bindings& constants,
              bool deadlocked) {
  const engines::StateView view(runtime.system(), runtime.layout(), runtime.state(), strings);
  const engines::StepInfo step{};
  const monitors::EngineState engine_state(step, view);
  const monitors::Moment moment(engine_state, 0, monitors::TimeScale{}, false,
                                deadlocked ? monitors::RunEnd::Deadlock : monitors::RunEnd::Cut);
  return formula_value(formula, moment, constants);
}

}  // namespace smcbip::fdir
