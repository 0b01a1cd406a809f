#include "smc/check/answer.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <string>

namespace smcbip::smc {
namespace {

using monitors::Verdict;

bool holds_at_least(monitors::Comparison c) {
  return c == monitors::Comparison::GreaterEqual || c == monitors::Comparison::Greater;
}

bool compare(double estimate, monitors::Comparison c, double theta) {
  switch (c) {
    case monitors::Comparison::GreaterEqual:
      return estimate >= theta;
    case monitors::Comparison::Greater:
      return estimate > theta;
    case monitors::Comparison::LessEqual:
      return estimate <= theta;
    case monitors::Comparison::Less:
      return estimate < theta;
  }
  return false;
}

double ratio(std::uint64_t x, std::uint64_t n) {
  return n == 0 ? 0.0 : static_cast<double>(x) / static_cast<double>(n);
}

}  // namespace

Method method_for(const monitors::Query& q, Method asked) {
  using K = monitors::Query::Kind;
  if (q.kind == K::Expectation) return Method::Mean;
  if (q.kind == K::Compare) return Method::Paired;
  if (asked == Method::Band) return Method::Band;
  const bool tests = asked == Method::Sprt || asked == Method::Ssp;
  if (asked == Method::Auto || (tests && q.kind == K::Estimate)) {
    return q.kind == K::Hypothesis ? Method::Sprt : Method::Pestim;
  }
  return asked;
}

Answer::Answer(const monitors::Query& q, const CheckOptions& options, double theta,
               std::uint64_t runs, QueryResult& result)
    : q_(&q), options_(options), theta_(theta), runs_(runs), r_(&result) {}

bool Answer::take(const Outcome& outcome, std::uint64_t index, engines::RunEnd end,
                  const std::string& failure) {
  if (outcome.verdict == Verdict::Undecided) return undecided(index, end, failure);
  ++r_->samples;
  if (r_->first_hit_horizon > 0 && outcome.verdict == Verdict::True &&
      std::isfinite(outcome.value)) {
    r_->first_hits.push_back(outcome.value);
  }
  return sample(outcome.verdict == Verdict::True, outcome.value);
}

bool Answer::undecided(std::uint64_t index, engines::RunEnd end, const std::string& failure) {
  ++r_->undecided;
  UndecidedRuns& why = r_->why_undecided;
  switch (end) {
    case engines::RunEnd::Limit:
      ++why.limit;
      break;
    case engines::RunEnd::Timelock:
      ++why.timelock;
      break;
    case engines::RunEnd::Error:
      if (why.error++ == 0) {
        why.first_error_run = index;
        why.first_error = failure;
      }
      break;
    case engines::RunEnd::Deadlock:
    case engines::RunEnd::Stopped:
    case engines::RunEnd::Absorbing:
      ++why.ended;
      break;
  }
  const std::uint64_t runs = r_->samples + r_->undecided;
  const auto give_up = [&](const std::string& why_text) {
    r_->error = why_text + ": " + undecided_text(why, options_.max_steps);
    return false;
  };
  switch (options_.undecided) {
    case UndecidedPolicy::Error:
      if (r_->undecided > 10 && r_->undecided * 100 > runs) {
        return give_up(std::to_string(r_->undecided) + " of " + std::to_string(runs) +
                       " runs undecided (more than 1%, --undecided error)");
      }
      return true;
    case UndecidedPolicy::Skip:
      if (r_->undecided >= kMaxSkippedRuns && r_->undecided > r_->samples) {
        return give_up("gave up after " + std::to_string(r_->undecided) +
                       " undecided runs against " + std::to_string(r_->samples) +
                       " decided (--undecided skip)");
      }
      return true;
    case UndecidedPolicy::Fail:
      if (end == engines::RunEnd::Error) {
        return give_up(
            "a run that failed is not a run where the property is false "
            "(--undecided fail)");
      }
      if (r_->method == Method::Mean) {
        return give_up(
            "an expectation has no value for a run left undecided, which "
            "--undecided fail cannot count (choose skip or error)");
      }
      ++r_->samples;
      return sample(false, 0);
  }
  return true;
}

std::string undecided_text(const UndecidedRuns& runs, std::uint64_t max_steps) {
  std::string text;
  const auto add = [&](std::uint64_t count, const std::string& what) {
    if (count == 0) return;
    text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
  };
  add(runs.limit, "cut at the step limit (--max-steps " + std::to_string(max_steps) +
                      ") before the query was decided: raise it, or bound the formula (an "
                      "unbounded G or F is decided only by a deadlock or a witness)");
  add(runs.timelock, "ended in a time-lock");
  add(runs.error, "ended in a model error (run " + std::to_string(runs.first_error_run) + ": " +
                      runs.first_error + ")");
  add(runs.ended, "ended (deadlock) before the formula was decided");
  return text.empty() ? "no run undecided" : text;
}

void Answer::finish() {
  if (r_->method == Method::Mean) {
    finish_mean();
    return;
  }
  if (r_->method == Method::Band) {
    const double epsilon = dkw_half_width(r_->samples, options_.alpha);
    r_->ci = {std::max(0.0, r_->estimate - epsilon), std::min(1.0, r_->estimate + epsilon)};
  }
  if (q_->kind == monitors::Query::Kind::Hypothesis && !r_->verdict && r_->error.empty()) {
    r_->verdict = compare(r_->estimate, q_->comparison, theta_);
  }
}

std::uint64_t Answer::target() const {
  switch (r_->method) {
    case Method::Pestim:
    case Method::Band:
      return chernoff_samples(options_.delta, options_.alpha);
    case Method::Ssp:
      return plan_ ? plan_->n : 0;
    case Method::Mean:
      return runs_;
    default:
      return 0;
  }
}

double Answer::test_position() const {
  if (!sprt_) return -1;
  const double span = sprt_->reject_threshold() - sprt_->accept_threshold();
  return std::clamp((sprt_->log_ratio() - sprt_->accept_threshold()) / span, 0.0, 1.0);
}

void Answer::finish_mean() {
  const double n = static_cast<double>(r_->samples);
  r_->estimate = sum_ / n;
  const double variance = n > 1 ? (squares_ - n * r_->estimate * r_->estimate) / (n - 1) : 0;
  const boost::math::normal normal;
  const double z = boost::math::quantile(normal, 1 - (1 - options_.confidence) / 2);
  const double half = z * std::sqrt(std::max(0.0, variance) / n);
  r_->ci = {r_->estimate - half, r_->estimate + half};
}

bool Answer::sample(bool satisfied, double value) {
  switch (r_->method) {
    case Method::Sprt: {
      if (!sprt_) sprt_.emplace(theta_, options_.delta, options_.alpha, options_.beta);
      const Decision d = sprt_->add(satisfied);
      r_->estimate = ratio(sprt_->successes(), sprt_->samples());
      if (d == Decision::Undecided) return true;
      r_->verdict = (d == Decision::AtLeast) == holds_at_least(q_->comparison);
      return false;
    }
    case Method::Ssp: {
      if (!plan_)
        plan_ = single_sampling_plan(theta_, options_.delta, options_.alpha, options_.beta);
      successes_ += satisfied;
      r_->estimate = ratio(successes_, r_->samples);
      if (r_->samples < plan_->n) return true;
      r_->verdict = (successes_ > plan_->c) == holds_at_least(q_->comparison);
      return false;
    }
    case Method::Pestim:
    case Method::Band: {
      // The same number of runs: Hoeffding's bound for one point is DKW's for all at once.
      if (!chernoff_n_) chernoff_n_ = chernoff_samples(options_.delta, options_.alpha);
      const std::uint64_t n = *chernoff_n_;
      successes_ += satisfied;
      r_->estimate = ratio(successes_, r_->samples);
      r_->ci = {std::max(0.0, r_->estimate - options_.delta),
                std::min(1.0, r_->estimate + options_.delta)};
      return r_->samples < n;
    }
    case Method::Ci: {
      if (!interval_) interval_.emplace(options_.delta, options_.alpha);
      const bool done = interval_->add(satisfied);
      r_->estimate = interval_->estimate();
      r_->ci = interval_->interval();
      return !done;
    }
    case Method::Bayes: {
      if (!bayes_) bayes_.emplace(options_.delta, options_.confidence);
      const bool done = bayes_->add(satisfied);
      r_->estimate = bayes_->estimate();
      r_->ci = bayes_->interval();
      return !done;
    }
    case Method::Mean:
    case Method::Auto:
    case Method::Paired:  // compare_probabilities answers those, not Answer
      break;
  }
  sum_ += value;
  squares_ += value * value;
  return r_->samples < runs_;
}

}  // namespace smcbip::smc
