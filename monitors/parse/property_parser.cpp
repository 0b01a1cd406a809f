// The property parser: recursive descent over the tokens of one file, building the AST.
//
// Hand-written like the BIP parser (bipc/parse/parser.h) for the same reasons: each error reads
// `expected X, got Y` at the offending token, the parser resynchronises on the next statement so
// one run reports independent errors, and nesting is bounded so hostile input gets a diagnostic.
//
// Precedence as PRISM's grammar (PrismParser.jj) and UPPAAL's, loosest first:
//   U R (right, with bounds)   -> <-> (right)   ||   &&   ! and the prefix temporal operators
//   comparisons   + -   * / %   unary -   primaries.
// A prefix temporal operator (X F G <> [] with its bound) takes the longest boolean expression
// after it, up to a closing parenthesis or a binary U/R: `F a && b` is `F (a && b)`, `F a U b` is
// `(F a) U b`. An atomic predicate is whatever the comparison level reads.
#include "monitors/parse/property_parser.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <utility>

#include "monitors/parse/property_checks.h"
#include "monitors/parse/property_lexer.h"

namespace smcbip::monitors {

namespace {

using detail::Token;
using detail::TokenKind;

// Thrown after an error was reported: the statement is abandoned and the parser resynchronises.
struct Abandon {};

// The deepest a formula's tree may grow, counting the operands of operator chains (`a && b &&
// ...`): deep enough for any formula a person or a generator writes, shallow enough that what
// walks the tree recursively keeps to a thread's stack.
constexpr int kMaxNestingDepth = 1000;

bool is_statement_keyword(const Token& t) {
  return t.kind == TokenKind::Name &&
         (t.text == "const" || t.text == "param" || t.text == "P" || t.text == "Pr" ||
          t.text == "E" || t.text == "A" || t.text == "simulate");
}

// Words of the language that cannot name a constant or parameter.
bool is_reserved(const Token& t) {
  static constexpr std::string_view kReserved[] = {
      "X",   "F",  "G",   "U",     "R",        "W",        "true", "false",
      "and", "or", "not", "imply", "deadlock", "timelock", "time", "init"};
  if (is_statement_keyword(t)) return true;
  for (std::string_view word : kReserved) {
    if (t.text == word) return true;
  }
  return false;
}

class Parser {
 public:
  Parser(detail::TokenStream& tokens, bipc::Diagnostics& diagnostics)
      : tokens_(tokens), diagnostics_(diagnostics) {}

  PropertyFile file() {
    PropertyFile out;
    while (peek().kind != TokenKind::End) {
      if (symbol(";")) continue;
      statement_start_ = tokens_.taken();
      try {
        statement(out);
      } catch (const Abandon&) {
        resynchronise();
      }
    }
    return out;
  }

 private:
  // Tokens.
  // A reference from peek() holds until the token is taken; one from take() until the next.
  const Token& peek(std::size_t ahead = 0) { return tokens_.peek(ahead); }
  const Token& take() { return tokens_.take(); }
  bool is_symbol(std::string_view text, std::size_t ahead = 0) {
    const Token& t = peek(ahead);
    return t.kind == TokenKind::Symbol && t.text == text;
  }
  bool is_word(std::string_view text, std::size_t ahead = 0) {
    const Token& t = peek(ahead);
    return t.kind == TokenKind::Name && t.text == text;
  }
  bool symbol(std::string_view text) {
    if (!is_symbol(text)) return false;
    take();
    return true;
  }
  [[noreturn]] void fail(const std::string& expected) {
    diagnostics_.error(peek().at, "expected " + expected + ", got " + describe(peek()));
    throw Abandon{};
  }
  void expect(std::string_view text, const std::string& context) {
    if (!symbol(text)) fail("'" + std::string(text) + "' " + context);
  }
  // After an error: on to the next `;`, or to a token that starts a line at its first column
  // or is a statement keyword starting a line (statements end at the end of their line).
  void resynchronise() {
    // The failing token may itself start the next statement (a statement cut short at the end
    // of its line); it is skipped only when the failed statement consumed nothing.
    if (tokens_.taken() > statement_start_ && starts_statement_line()) return;
    std::uint32_t line = peek().at.line;
    take();
    while (peek().kind != TokenKind::End) {
      if (symbol(";")) return;
      if (peek().at.line != line && starts_statement_line()) return;
      line = take().at.line;
    }
  }
  // Whether the next token starts its line and a statement.
  bool starts_statement_line() {
    const Token& t = peek();
    const Token* before = tokens_.previous();
    const bool first_on_line = before == nullptr || before->at.line != t.at.line;
    return first_on_line && (t.at.column == 1 || is_statement_keyword(t));
  }

  // Statements.
  void statement(PropertyFile& out) {
    if (is_word("const") || is_word("param")) {
      out.declarations.push_back(declaration());
    } else if (is_word("A") || (is_word("E") && (is_symbol("<>", 1) || is_symbol("[]", 1)))) {
      out.queries.push_back(path_quantified());
    } else if (is_word("P") || is_word("Pr") || is_word("E")) {
      out.queries.push_back(is_word("P") ? p_query() : is_word("Pr") ? pr_query() : e_query());
    } else if (is_word("simulate")) {
      out.queries.push_back(simulate_query());
    } else {
      unsupported_query();
      fail("a query (P, Pr, E, simulate, A[] or E<>) or a declaration (const or param)");
    }
    // Statements end with `;` or at the end of their line.
    if (!symbol(";") && peek().kind != TokenKind::End &&
        peek().at.line == tokens_.previous()->at.line) {
      fail("';' or a new line after the statement");
    }
  }

  Declaration declaration() {
    Declaration d;
    d.at = peek().at;
    d.kind = take().text == "const" ? Declaration::Kind::Constant : Declaration::Kind::Parameter;
    if ((is_word("int") || is_word("double")) && peek(1).kind == TokenKind::Name) take();
    if (is_word("bool") && peek(1).kind == TokenKind::Name) {
      fail("a number: constants are numbers (write 1 or 0 for a boolean)");
    }
    if (peek().kind != TokenKind::Name || is_reserved(peek())) fail("the name being declared");
    d.name = take().text;
    expect("=", "after the declared name");
    if (d.kind == Declaration::Kind::Constant) {
      d.value = number("the constant's value");
      return d;
    }
    if (symbol("{")) {
      do {
        d.values.push_back(number("a parameter value"));
      } while (symbol(","));
      expect("}", "to close the list of values");
      return d;
    }
    d.range = true;
    d.values.push_back(number("the first value of the range (start:stop:step) or '{'"));
    expect(":", "between the range's start and stop (start:stop:step)");
    d.values.push_back(number("the range's stop"));
    expect(":", "between the range's stop and step (start:stop:step)");
    d.values.push_back(number("the range's step"));
    return d;
  }

  Query p_query() {
    Query q;
    q.at = take().at;  // P
    if (symbol("=?")) {
      q.kind = Query::Kind::Estimate;
    } else {
      q.kind = Query::Kind::Hypothesis;
      q.comparison = comparison("'=?' or a comparison (>=, >, <=, <) after P");
      q.threshold = value("the probability threshold");
    }
    expect("[", "before the path formula");
    q.formula = formula();
    expect("]", "after the path formula");
    return q;
  }

  Query pr_query() {
    Query q;
    q.at = take().at;  // Pr
    q.pr_form = true;
    bounded_formula(q.run, q.formula);
    if (is_symbol(">=") || is_symbol(">") || is_symbol("<=") || is_symbol("<")) {
      q.comparison = comparison("a comparison");
      if (is_word("Pr")) {
        // Pr[<=T](phi) >= Pr[<=T2](psi): two probabilities compared (UPPAAL).
        q.kind = Query::Kind::Compare;
        take();
        bounded_formula(q.other_run, q.other);
        return q;
      }
      q.kind = Query::Kind::Hypothesis;
      q.threshold = value("the probability threshold");
    }
    return q;
  }

  // `[<=T](phi)` or `[#<=K](phi)` after Pr.
  void bounded_formula(Bound& run, std::unique_ptr<Formula>& phi) {
    expect("[", "after Pr (Pr[<=T] or Pr[#<=K])");
    run = run_bound();
    expect("]", "after the run bound");
    expect("(", "before the path formula");
    phi = formula();
    expect(")", "after the path formula");
  }

  // simulate [<=T; N] { e1, e2, ... } (UPPAAL): N runs' trajectories of the expressions.
  Query simulate_query() {
    Query q;
    q.kind = Query::Kind::Simulate;
    q.at = take().at;  // simulate
    q.pr_form = true;
    expect("[", "after simulate (simulate [<=T; N] { e1, e2 })");
    q.run = run_bound();
    expect(";", "between the run bound and the number of runs");
    q.runs = value("the number of runs");
    expect("]", "after the number of runs");
    expect("{", "before the expressions to follow");
    do {
      q.series.push_back(expression());
    } while (symbol(","));
    expect("}", "after the expressions to follow");
    return q;
  }

  // `A[] phi` and `E<> phi` (UPPAAL): exact questions over every reachable state, which the
  // invariant prover answers, not statistics.
  Query path_quantified() {
    Query q;
    q.at = peek().at;
    const bool all = take().text == "A";
    if (all && is_symbol("<>")) {
      fail("'[]' after A: A<> (inevitability) is not supported; P>=1 [ F phi ] estimates it");
    }
    if (!all && is_symbol("[]")) {
      fail("'<>' after E: E[] is not supported; P>0 [ G phi ] estimates it");
    }
    if (!symbol(all ? "[]" : "<>")) fail(all ? "'[]' after A (A[] phi)" : "'<>' after E");
    q.kind = all ? Query::Kind::Invariant : Query::Kind::Reachable;
    q.formula = formula();
    return q;
  }

  // Queries of other tools that smcbip does not answer, with the form it answers instead.
  void unsupported_query() {
    const Token& t = peek();
    if (t.kind != TokenKind::Name) return;
    const bool question = is_symbol("=?", 1) || is_symbol("[", 1) || is_symbol(">=", 1) ||
                          is_symbol("<=", 1) || is_symbol(">", 1) || is_symbol("<", 1);
    if (!question) return;
    if (t.text == "S") {
      unsupported(t.at,
                  "steady-state queries (S) are not supported: estimate a long-run "
                  "probability with P=? [ F[T,T] phi ] for a large T");
    }
    if (t.text == "R") {
      unsupported(t.at,
                  "reward queries (R) are not supported: use E[<=T; N](int: e) for a "
                  "cumulative reward, E[<=T; N](last: e) for an instantaneous one");
    }
    if (t.text == "Pmin" || t.text == "Pmax") {
      unsupported(t.at, t.text +
                            " is not supported: the models have no nondeterminism to "
                            "resolve; use P=?");
    }
  }
  [[noreturn]] void unsupported(bipc::Location at, const std::string& message) {
    diagnostics_.error(at, message);
    throw Abandon{};
  }

  // E[<=T; N](max: e) (UPPAAL), or E=? [ max: e ] (the runs' length and number left to the
  // checking).
  Query e_query() {
    Query q;
    q.kind = Query::Kind::Expectation;
    q.at = take().at;  // E
    q.pr_form = !symbol("=?");
    if (!q.pr_form) {
      expect("[", "after E=?");
      observed(q);
      expect("]", "after the observed expression");
      return q;
    }
    expect("[", "after E (E[<=T; N] or E=?)");
    q.run = run_bound();
    expect(";", "between the run bound and the number of runs");
    q.runs = value("the number of runs");
    expect("]", "after the number of runs");
    expect("(", "before max:, min:, last:, int: or count:");
    observed(q);
    expect(")", "after the observed expression");
    return q;
  }

  // `max: e`, `min: e`, `last: e`, `int: e` or `count: fired(c)`.
  void observed(Query& q) {
    static constexpr std::pair<std::string_view, Observation> kObservations[] = {
        {"max", Observation::Max},
        {"min", Observation::Min},
        {"last", Observation::Last},
        {"int", Observation::Integral},
        {"count", Observation::Count}};
    const auto found = std::find_if(std::begin(kObservations), std::end(kObservations),
                                    [&](const auto& o) { return is_word(o.first); });
    if (found == std::end(kObservations)) fail("'max', 'min', 'last', 'int' or 'count'");
    take();
    q.observe = found->second;
    expect(":", "after " + std::string(found->first));
    if (q.observe == Observation::Count && !(is_word("fired") && is_symbol("(", 1))) {
      fail("fired(connector) after count: (count: fired(c) counts the steps that fire c)");
    }
    q.observed = expression();
  }

  // `<=T` (time) or `#<=K` (steps), inside a query's brackets.
  Bound run_bound() {
    Bound b;
    if (symbol("#")) {
      expect("<=", "after '#' (#<=K bounds the run by K steps)");
      b.kind = Bound::Kind::Steps;
      b.high = value("the number of steps");
      return b;
    }
    if (!symbol("<=")) fail("'<=T' or '#<=K' (the run's time or step bound)");
    b.kind = Bound::Kind::Time;
    b.low = zero_at(peek().at);
    b.high = value("the run's time bound");
    return b;
  }

  Comparison comparison(const std::string& expected) {
    static constexpr std::pair<std::string_view, Comparison> kComparisons[] = {
        {">=", Comparison::GreaterEqual},
        {">", Comparison::Greater},
        {"<=", Comparison::LessEqual},
        {"<", Comparison::Less}};
    for (const auto& [text, comparison] : kComparisons) {
      if (symbol(text)) return comparison;
    }
    fail(expected);
  }

  // Values: numbers as written, or names of constants and parameters.
  static Value value_of(const Token& t) {
    Value v;
    v.at = t.at;
    v.text = t.text;
    v.number = t.number;
    v.integral = t.integral;
    v.unit = t.unit;
    return v;
  }
  static Value zero_at(bipc::Location at) {
    Value v;
    v.at = at;
    v.text = "0";
    v.integral = true;
    return v;
  }
  // A number, possibly negative (constants and parameters; checks refuse negative bounds).
  Value number(const std::string& expected) {
    const bool negative = is_symbol("-") && peek(1).kind == TokenKind::Number;
    if (negative) take();
    if (peek().kind != TokenKind::Number) fail(expected);
    Value v = value_of(take());
    if (negative) {
      v.text = "-" + v.text;
      v.number = -v.number;
    }
    return v;
  }
  Value value(const std::string& expected) {
    if (peek().kind == TokenKind::Name && !is_reserved(peek())) {
      Value v;
      v.at = peek().at;
      v.name = take().text;
      return v;
    }
    return number(expected + " (a number or a declared name)");
  }

  // Formulas.
  struct DepthGuard {
    Parser& parser;
    explicit DepthGuard(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxNestingDepth) {
        parser.diagnostics_.error(parser.peek().at, "property nested too deeply (more than " +
                                                        std::to_string(kMaxNestingDepth) +
                                                        " levels)");
        throw Abandon{};
      }
    }
    ~DepthGuard() { --parser.depth_; }
  };

  static std::unique_ptr<Formula> make(Formula::Kind kind, bipc::Location at) {
    auto f = std::make_unique<Formula>();
    f->kind = kind;
    f->at = at;
    return f;
  }

  // One more level of the tree below an operator chain; false (reported) beyond the limit.
  void deepen(int& levels) {
    ++levels;
    if (++depth_ > kMaxNestingDepth) too_deep();
  }
  [[noreturn]] void too_deep() {
    diagnostics_.error(peek().at, "property nested too deeply (more than " +
                                      std::to_string(kMaxNestingDepth) + " levels of operators)");
    throw Abandon{};
  }
  // Restores the depth an operator chain added, however the chain ends.
  struct ChainDepth {
    Parser& parser;
    int levels = 0;
    ~ChainDepth() { parser.depth_ -= levels; }
  };

  bool is_any(std::initializer_list<std::string_view> symbols,
              std::initializer_list<std::string_view> words) {
    for (std::string_view s : symbols) {
      if (is_symbol(s)) return true;
    }
    for (std::string_view w : words) {
      if (is_word(w)) return true;
    }
    return false;
  }

  std::unique_ptr<Formula> formula() { return temporal_binary(); }

  // phi U[a,b] psi, phi R[a,b] psi: the loosest operators, right-associative.
  std::unique_ptr<Formula> temporal_binary() {
    const DepthGuard guard(*this);
    std::unique_ptr<Formula> left = implication();
    if (is_word("W")) {
      unsupported(peek().at, "the weak until W is not supported: write (a U b) || G a");
    }
    if (is_symbol("-->")) {
      unsupported(peek().at, "leads-to (-->) is not supported: write G (a -> F b)");
    }
    if (!is_word("U") && !is_word("R")) return left;
    const Formula::Kind kind = is_word("U") ? Formula::Kind::Until : Formula::Kind::Release;
    auto f = make(kind, take().at);
    f->bound = temporal_bound();
    f->operands.push_back(std::move(left));
    f->operands.push_back(temporal_binary());
    return f;
  }

  // a -> b, a <-> b (also =>, imply, <=>): right-associative.
  std::unique_ptr<Formula> implication() {
    const DepthGuard guard(*this);
    std::unique_ptr<Formula> left = disjunction();
    Formula::Kind kind;
    if (is_any({"->", "=>"}, {"imply"})) {
      kind = Formula::Kind::Implies;
    } else if (is_any({"<->", "<=>"}, {})) {
      kind = Formula::Kind::Iff;
    } else {
      return left;
    }
    auto f = make(kind, take().at);
    f->operands.push_back(std::move(left));
    f->operands.push_back(implication());
    return f;
  }

  std::unique_ptr<Formula> disjunction() {
    ChainDepth chain{*this};
    std::unique_ptr<Formula> left = conjunction();
    while (is_any({"||", "|"}, {"or"})) {
      deepen(chain.levels);
      auto f = make(Formula::Kind::Or, take().at);
      f->operands.push_back(std::move(left));
      f->operands.push_back(conjunction());
      left = std::move(f);
    }
    return left;
  }

  std::unique_ptr<Formula> conjunction() {
    ChainDepth chain{*this};
    std::unique_ptr<Formula> left = unary();
    while (is_any({"&&", "&"}, {"and"})) {
      deepen(chain.levels);
      auto f = make(Formula::Kind::And, take().at);
      f->operands.push_back(std::move(left));
      f->operands.push_back(unary());
      left = std::move(f);
    }
    return left;
  }

  // ! phi (also not), and the prefix temporal operators, whose operand is the longest boolean
  // expression that follows (no U or R outside parentheses).
  std::unique_ptr<Formula> unary() {
    const DepthGuard guard(*this);
    Formula::Kind kind = Formula::Kind::True;
    if (is_any({"!"}, {"not"})) {
      kind = Formula::Kind::Not;
    } else if (is_word("X")) {
      kind = Formula::Kind::Next;
    } else if (is_word("F") || is_symbol("<>")) {
      kind = Formula::Kind::Finally;
    } else if (is_word("G") || is_symbol("[]")) {
      kind = Formula::Kind::Globally;
    } else {
      return primary_formula();
    }
    auto f = make(kind, take().at);
    if (kind == Formula::Kind::Finally || kind == Formula::Kind::Globally) {
      f->bound = temporal_bound();
    }
    f->operands.push_back(kind == Formula::Kind::Not ? unary() : implication());
    return f;
  }

  // `[a,b]`, `[<=T]`, `[#<=k]`, `{k}`, `<=T`, `<=#k`, or nothing.
  Bound temporal_bound() {
    Bound b;
    if (is_symbol("[") && (is_symbol("#", 1) || is_symbol("<=", 1))) {
      take();
      b = run_bound();
      expect("]", "to close the bound");
    } else if (symbol("[")) {
      b.kind = Bound::Kind::Time;
      b.low = value("the interval's lower bound");
      expect(",", "between the interval's bounds");
      b.high = value("the interval's upper bound");
      expect("]", "to close the interval");
    } else if (symbol("{")) {
      b.kind = Bound::Kind::Steps;
      b.high = value("the number of steps");
      expect("}", "after the number of steps");
    } else if (is_symbol("<=")) {
      const bipc::Location at = take().at;
      if (symbol("#")) {
        b.kind = Bound::Kind::Steps;
        b.high = value("the number of steps");
      } else {
        b.kind = Bound::Kind::Time;
        b.low = zero_at(at);
        b.high = value("the time bound");
      }
    }
    return b;
  }

  static bool starts_expression_operator(const Token& t) {
    if (t.kind != TokenKind::Symbol) return false;
    static constexpr std::string_view kOperators[] = {"+",  "-", "*",  "/",  "%",  "<",
                                                      "<=", ">", ">=", "==", "!=", "="};
    for (std::string_view op : kOperators) {
      if (t.text == op) return true;
    }
    return false;
  }

  // true, false, a parenthesised formula, or an atomic predicate. A parenthesised atom may be
  // the first operand of arithmetic or a comparison: `(x + 1) * 2 > y`.
  std::unique_ptr<Formula> primary_formula() {
    const bipc::Location at = peek().at;
    if ((is_word("true") || is_word("false")) && !starts_expression_operator(peek(1))) {
      return make(take().text == "true" ? Formula::Kind::True : Formula::Kind::False, at);
    }
    std::unique_ptr<Expr> first;
    if (symbol("(")) {
      std::unique_ptr<Formula> inner = formula();
      expect(")", "to close the parenthesis");
      if (inner->kind != Formula::Kind::Atom || !starts_expression_operator(peek())) return inner;
      first = std::move(inner->atom);
    }
    auto f = make(Formula::Kind::Atom, at);
    f->atom = comparison_expression(std::move(first));
    return f;
  }

  // State expressions.
  static std::unique_ptr<Expr> make_expr(Expr::Kind kind, bipc::Location at) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->at = at;
    return e;
  }
  static std::unique_ptr<Expr> binary(Expr::Kind kind, bipc::Location at,
                                      std::unique_ptr<Expr> left, std::unique_ptr<Expr> right) {
    auto e = make_expr(kind, at);
    e->operands.push_back(std::move(left));
    e->operands.push_back(std::move(right));
    return e;
  }

  std::unique_ptr<Expr> expression() { return comparison_expression(nullptr); }

  // `first`: an operand already read (a parenthesised one), or null.
  std::unique_ptr<Expr> comparison_expression(std::unique_ptr<Expr> first) {
    const DepthGuard guard(*this);
    std::unique_ptr<Expr> left = additive(std::move(first));
    static constexpr std::pair<std::string_view, Expr::Kind> kComparisons[] = {
        {"<", Expr::Kind::Less},          {"<=", Expr::Kind::LessEqual}, {">", Expr::Kind::Greater},
        {">=", Expr::Kind::GreaterEqual}, {"==", Expr::Kind::Equal},     {"=", Expr::Kind::Equal},
        {"!=", Expr::Kind::NotEqual}};
    for (const auto& [text, kind] : kComparisons) {
      if (is_symbol(text)) {
        const bipc::Location at = take().at;
        return binary(kind, at, std::move(left), additive(nullptr));
      }
    }
    return left;
  }

  std::unique_ptr<Expr> additive(std::unique_ptr<Expr> first) {
    ChainDepth chain{*this};
    std::unique_ptr<Expr> left = multiplicative(std::move(first));
    while (is_symbol("+") || is_symbol("-")) {
      deepen(chain.levels);
      const Expr::Kind kind = peek().text == "+" ? Expr::Kind::Add : Expr::Kind::Subtract;
      const bipc::Location at = take().at;
      left = binary(kind, at, std::move(left), multiplicative(nullptr));
    }
    return left;
  }

  std::unique_ptr<Expr> multiplicative(std::unique_ptr<Expr> first) {
    ChainDepth chain{*this};
    std::unique_ptr<Expr> left = first ? std::move(first) : prefix();
    while (is_symbol("*") || is_symbol("/") || is_symbol("%")) {
      deepen(chain.levels);
      const Expr::Kind kind = peek().text == "*"   ? Expr::Kind::Multiply
                              : peek().text == "/" ? Expr::Kind::Divide
                                                   : Expr::Kind::Modulo;
      const bipc::Location at = take().at;
      left = binary(kind, at, std::move(left), prefix());
    }
    return left;
  }

  std::unique_ptr<Expr> prefix() {
    const DepthGuard guard(*this);
    if (!is_symbol("-")) return primary_expression();
    auto e = make_expr(Expr::Kind::Negate, take().at);
    e->operands.push_back(prefix());
    return e;
  }

  std::unique_ptr<Expr> primary_expression() {
    const Token& t = peek();
    if (t.kind == TokenKind::Number) {
      auto e = make_expr(Expr::Kind::Number, t.at);
      e->value = value_of(take());
      return e;
    }
    if (symbol("(")) {
      std::unique_ptr<Expr> inner = expression();
      expect(")", "to close the parenthesis");
      return inner;
    }
    if (t.kind == TokenKind::Label) return label();
    if (t.kind != TokenKind::Name) fail("a formula or an expression");
    const bool builtin =
        t.text == "deadlock" || t.text == "timelock" || t.text == "time" || t.text == "init";
    if (is_reserved(t) && !builtin && !is_symbol(".", 1)) {
      fail("a formula or an expression ('" + t.text + "' is an operator)");
    }
    if (t.text == "true" || t.text == "false") {
      auto e = make_expr(Expr::Kind::Bool, t.at);
      e->boolean = take().text == "true";
      return e;
    }
    if (is_symbol("(", 1)) return call();
    auto e = make_expr(Expr::Kind::Name, t.at);
    e->path = path();
    mark_builtin(*e);
    return e;
  }

  // PRISM's built-in labels: "deadlock" and "init".
  std::unique_ptr<Expr> label() {
    const Token& t = peek();
    if (t.text != "deadlock" && t.text != "init") {
      diagnostics_.error(t.at, "unknown label \"" + t.text +
                                   "\": the labels are \"deadlock\" and \"init\"; name other "
                                   "states by their predicates (Atom.place, Atom.x == 3)");
      throw Abandon{};
    }
    auto e = make_expr(Expr::Kind::Name, t.at);
    e->path = take().text;
    mark_builtin(*e);
    return e;
  }

  // The language's own names: the global time, the initial state, deadlock and time-lock.
  static void mark_builtin(Expr& e) {
    static constexpr std::pair<std::string_view, Reference::Kind> kBuiltins[] = {
        {"time", Reference::Kind::Time},
        {"init", Reference::Kind::Initial},
        {"deadlock", Reference::Kind::Deadlock},
        {"timelock", Reference::Kind::Timelock}};
    for (const auto& [name, kind] : kBuiltins) {
      if (e.path == name) {
        e.reference.kind = kind;
        e.is_bool = kind != Reference::Kind::Time;
      }
    }
  }

  // A dotted path: Channel.id_channel, Syst.node3.status.
  std::string path() {
    std::string out = take().text;
    while (is_symbol(".")) {
      take();
      if (peek().kind != TokenKind::Name) fail("a name after '.'");
      out += "." + take().text;
    }
    return out;
  }

  // abs(e), min(a, b), max(a, b), fired(connector).
  std::unique_ptr<Expr> call() {
    const Token& name = peek();
    const bipc::Location at = name.at;
    const std::string function = take().text;
    take();  // (
    if (function == "fired") {
      auto e = make_expr(Expr::Kind::Fired, at);
      if (peek().kind != TokenKind::Name) fail("the name of a connector (or atom.port) in fired()");
      e->path = path();
      expect(")", "after the name in fired()");
      return e;
    }
    const std::size_t arity = function == "abs"                        ? 1
                              : function == "min" || function == "max" ? 2
                                                                       : 0;
    if (arity == 0) {
      diagnostics_.error(at,
                         "unknown function '" + function + "': expected abs, min, max or fired");
      throw Abandon{};
    }
    auto e = make_expr(Expr::Kind::Call, at);
    e->path = function;
    e->operands.push_back(expression());
    if (arity == 2) {
      expect(",", "between the arguments of " + function);
      e->operands.push_back(expression());
    }
    expect(")", "after the argument" + std::string(arity == 2 ? "s" : "") + " of " + function);
    return e;
  }

  detail::TokenStream& tokens_;
  bipc::Diagnostics& diagnostics_;
  std::size_t statement_start_ = 0;
  int depth_ = 0;
};

/// `NAME=v` and `NAME=v1,v2,...` as the list `NAME={v1,v2,...}`; ranges and braced lists as
/// written.
std::string braced_values(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) return text;
  const std::size_t first = text.find_first_not_of(" \t", equals + 1);
  if (first == std::string::npos || text[first] == '{' ||
      text.find(':', equals) != std::string::npos) {
    return text;
  }
  return text.substr(0, first) + "{" + text.substr(first) + "}";
}

/// Reads `NAME=values` as the declaration `param NAME=values`.
std::optional<Declaration> given_parameter(const std::string& written, std::uint32_t source,
                                           bipc::Diagnostics& diagnostics) {
  const std::string text = braced_values(written);
  detail::TokenStream tokens(text, source, diagnostics);
  Token keyword;
  keyword.kind = TokenKind::Name;
  keyword.text = "param";
  keyword.at = tokens.peek().at;
  tokens.push_front(keyword);
  const std::size_t errors = diagnostics.error_count();
  PropertyFile given = Parser(tokens, diagnostics).file();
  if (diagnostics.error_count() != errors) return std::nullopt;
  if (given.declarations.size() != 1 || !given.queries.empty()) {
    diagnostics.error({source, 1, 1},
                      "expected one parameter: NAME=start:stop:step, NAME=v1,v2,... or NAME=v");
    return std::nullopt;
  }
  return std::move(given.declarations.front());
}

/// Gives the file the parameters of the command line: each replaces the file's declaration of
/// its name (keeping its place, so that uses before it stay errors) or comes before the file.
void give_parameters(const std::vector<std::string>& parameters, ParsedProperties& parsed) {
  std::vector<Declaration>& declarations = parsed.file.declarations;
  for (const std::string& text : parameters) {
    const std::uint32_t source = parsed.sources.add("--param");
    std::optional<Declaration> given = given_parameter(text, source, parsed.diagnostics);
    if (!given) continue;
    const auto same = std::find_if(declarations.begin(), declarations.end(),
                                   [&](const Declaration& d) { return d.name == given->name; });
    if (same == declarations.end()) {
      given->at = {source, 0, 0};
      declarations.insert(declarations.begin(), std::move(*given));
    } else {
      given->at = same->at;
      *same = std::move(*given);
    }
  }
}

}  // namespace

ParsedProperties parse_properties(std::string_view text, const std::string& path,
                                  const std::vector<std::string>& parameters) {
  ParsedProperties parsed;
  const std::uint32_t file = parsed.sources.add(path);
  detail::TokenStream tokens(text, file, parsed.diagnostics);
  parsed.file = Parser(tokens, parsed.diagnostics).file();
  if (parsed.ok()) give_parameters(parameters, parsed);
  if (parsed.ok()) detail::check_properties(parsed.file, parsed.diagnostics);
  parsed.diagnostics.sort_by_location();
  return parsed;
}

ParsedProperties load_properties(const std::string& path,
                                 const std::vector<std::string>& parameters) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ParsedProperties parsed;
    parsed.diagnostics.error({parsed.sources.add(path), 0, 0}, "cannot read the property file");
    return parsed;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_properties(text, path, parameters);
}

}  // namespace smcbip::monitors
