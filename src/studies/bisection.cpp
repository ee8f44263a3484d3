#include "studies/bisection.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace coldspray::studies {

namespace {

bool same_value(double a, double b) {
  return std::abs(a - b) <= ThresholdCache::kRelativeTolerance * std::max(std::abs(a), std::abs(b));
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Where to cut the bracket (lo, hi): at the guide's guess, kept clear of the ends, or at the
// midpoint (find_threshold).
class Cutter {
 public:
  Cutter(const ThresholdGuide& guide, double tol) : guide_(guide), tol_(tol) {}

  double next(double lo, double hi) {
    guided_ = false;
    const double mid = 0.5 * (lo + hi);
    if (!guide_ || slow_cuts_ >= 2) {
      slow_cuts_ = 0;
      return mid;
    }
    const double guess = guide_(lo, hi);
    if (!std::isfinite(guess)) return mid;
    guided_ = true;
    const double clear = std::min(0.4 * tol_, 0.25 * (hi - lo));
    return std::clamp(guess, lo + clear, hi - clear);
  }

  // The bracket's width before and after the last cut.
  void narrowed(double before, double after) {
    if (guided_) slow_cuts_ = after > 0.5 * before ? slow_cuts_ + 1 : 0;
  }

 private:
  const ThresholdGuide& guide_;
  double tol_;
  bool guided_ = false;
  int slow_cuts_ = 0;
};

}  // namespace

std::optional<std::pair<double, bool>> ThresholdCache::find(double value) const {
  // The nearest stored values on either side are the only candidates.
  auto above = results_.lower_bound(value);
  if (above != results_.end() && same_value(above->first, value)) return *above;
  if (above != results_.begin()) {
    auto below = std::prev(above);
    if (same_value(below->first, value)) return *below;
  }
  return std::nullopt;
}

void ThresholdCache::insert(double value, bool result) {
  if (auto hit = find(value)) {
    results_[hit->first] = result;
    return;
  }
  results_.emplace(value, result);
}

std::string to_string(ThresholdStatus s) {
  switch (s) {
    case ThresholdStatus::Found:
      return "found";
    case ThresholdStatus::NotBracketed:
      return "not bracketed";
    case ThresholdStatus::EvaluationLimit:
      return "evaluation limit";
    case ThresholdStatus::NonMonotone:
      return "non-monotone";
  }
  return "unknown";
}

ThresholdResult find_threshold(const std::function<bool(double)>& predicate, double lo, double hi,
                               double tol, int max_evals, ThresholdCache* cache,
                               const ThresholdLimits& limits, const ThresholdGuide& guide) {
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("find_threshold: need finite lo < hi");
  if (!(tol >= 1e-8 * std::max(std::abs(lo), std::abs(hi))) || !(tol > 0.0))
    throw std::invalid_argument("find_threshold: tol must be > 0 and >= 1e-8 max(|lo|, |hi|)");
  if (max_evals < 2) throw std::invalid_argument("find_threshold: max_evals must be >= 2");
  if (!(limits.floor <= lo) || !(hi <= limits.ceiling))
    throw std::invalid_argument("find_threshold: need floor <= lo and hi <= ceiling");

  ThresholdCache local;
  ThresholdCache& known = cache ? *cache : local;
  ThresholdResult r;
  // The bracket from this search's results, and the extremes over every result known for the
  // predicate (the cache's included) for the monotonicity check.
  double lowest_true = std::numeric_limits<double>::infinity();
  double highest_false = -std::numeric_limits<double>::infinity();
  double any_lowest_true = lowest_true, any_highest_false = highest_false;
  for (const auto& [value, result] : known.results()) {
    if (result)
      any_lowest_true = std::min(any_lowest_true, value);
    else
      any_highest_false = std::max(any_highest_false, value);
  }

  // The result at v (from the cache or the predicate), nullopt once the budget is spent.
  auto evaluate = [&](double v) -> std::optional<bool> {
    ThresholdEvaluation e;
    if (auto hit = known.find(v)) {
      e = {hit->first, hit->second, true};
    } else {
      if (r.predicate_calls >= max_evals) return std::nullopt;
      e = {v, predicate(v), false};
      ++r.predicate_calls;
      known.insert(v, e.result);
    }
    r.evaluations.push_back(e);
    if (e.result) {
      lowest_true = std::min(lowest_true, e.value);
      any_lowest_true = std::min(any_lowest_true, e.value);
    } else {
      highest_false = std::max(highest_false, e.value);
      any_highest_false = std::max(any_highest_false, e.value);
    }
    return e.result;
  };
  auto monotone = [&] { return !(any_lowest_true < any_highest_false); };
  auto finish = [&](ThresholdStatus status, std::string message) {
    r.status = status;
    r.message = std::move(message);
    if (std::isfinite(lowest_true)) r.threshold = r.upper = lowest_true;
    if (std::isfinite(highest_false) && highest_false < lowest_true) r.lower = highest_false;
    return r;
  };
  auto non_monotone = [&] {
    r.conflict = std::make_pair(any_lowest_true, any_highest_false);
    return finish(ThresholdStatus::NonMonotone, "non-monotone: true at " + number(any_lowest_true) +
                                                    " but false at " + number(any_highest_false));
  };

  const bool lo_true = *evaluate(lo);
  if (!monotone()) return non_monotone();
  const bool hi_true = *evaluate(hi);
  if (!monotone()) return non_monotone();

  // Bracketing: step outward by the initial width until the result changes, down from lo while
  // true (not below the floor) or up from hi while false (not above the ceiling).
  if (lo_true || !hi_true) {
    const bool down = lo_true;
    const double limit = down ? limits.floor : limits.ceiling;
    const double step = down ? lo - hi : hi - lo;
    for (double v = down ? lo : hi;;) {
      if (down ? v <= limit : v >= limit)
        return finish(ThresholdStatus::NotBracketed,
                      (down ? "true down to the floor " : "false up to the ceiling ") + number(v));
      v = down ? std::max(v + step, limit) : std::min(v + step, limit);
      const std::optional<bool> res = evaluate(v);
      if (!res)
        return finish(
            ThresholdStatus::NotBracketed,
            down ? "evaluation limit reached stepping down, still true at " + number(lowest_true)
                 : "evaluation limit reached stepping up, still false at " + number(highest_false));
      if (!monotone()) return non_monotone();
      if (*res != down) break;  // the first false going down, the first true going up
    }
  }

  // Bisection of (highest false, lowest true), or the guide's cuts.
  Cutter cutter(guide, tol);
  while (lowest_true - highest_false > tol) {
    const double before = lowest_true - highest_false;
    const std::optional<bool> res = evaluate(cutter.next(highest_false, lowest_true));
    if (!res)
      return finish(ThresholdStatus::EvaluationLimit, "evaluation limit reached with bracket [" +
                                                          number(highest_false) + ", " +
                                                          number(lowest_true) + "]");
    if (!monotone()) return non_monotone();
    if (!(lowest_true - highest_false < before))  // a cache hit on a bracket end: no progress
      return finish(ThresholdStatus::EvaluationLimit, "bracket at the cache's resolution");
    cutter.narrowed(before, lowest_true - highest_false);
  }
  return finish(ThresholdStatus::Found,
                "threshold in [" + number(highest_false) + ", " + number(lowest_true) + "]");
}

}  // namespace coldspray::studies
