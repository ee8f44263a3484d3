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

namespace {

// One search's state: the results it has seen, its budget of predicate calls and the bracket it
// has narrowed; each phase of find_threshold (the ends, bracketing, bisection) is one method.
class ThresholdSearch {
 public:
  ThresholdSearch(const std::function<bool(double)>& predicate, int max_evals,
                  ThresholdCache& known)
      : predicate_(predicate), max_evals_(max_evals), known_(known) {
    // The extremes over every result known for the predicate (the cache's included), for the
    // monotonicity check; the bracket itself is from this search's results only.
    for (const auto& [value, result] : known.results()) {
      if (result)
        any_lowest_true_ = std::min(any_lowest_true_, value);
      else
        any_highest_false_ = std::max(any_highest_false_, value);
    }
  }

  // The result at v (from the cache or the predicate), nullopt once the budget is spent.
  std::optional<bool> evaluate(double v) {
    ThresholdEvaluation e;
    if (auto hit = known_.find(v)) {
      e = {hit->first, hit->second, true};
    } else {
      if (r_.predicate_calls >= max_evals_) return std::nullopt;
      e = {v, predicate_(v), false};
      ++r_.predicate_calls;
      known_.insert(v, e.result);
    }
    r_.evaluations.push_back(e);
    if (e.result) {
      lowest_true_ = std::min(lowest_true_, e.value);
      any_lowest_true_ = std::min(any_lowest_true_, e.value);
    } else {
      highest_false_ = std::max(highest_false_, e.value);
      any_highest_false_ = std::max(any_highest_false_, e.value);
    }
    return e.result;
  }

  bool monotone() const { return !(any_lowest_true_ < any_highest_false_); }
  double width() const { return lowest_true_ - highest_false_; }
  double lowest_true() const { return lowest_true_; }
  double highest_false() const { return highest_false_; }

  ThresholdResult finish(ThresholdStatus status, std::string message) {
    r_.status = status;
    r_.message = std::move(message);
    if (std::isfinite(lowest_true_)) r_.threshold = r_.upper = lowest_true_;
    if (std::isfinite(highest_false_) && highest_false_ < lowest_true_) r_.lower = highest_false_;
    return r_;
  }

  ThresholdResult non_monotone() {
    r_.conflict = std::make_pair(any_lowest_true_, any_highest_false_);
    return finish(ThresholdStatus::NonMonotone, "non-monotone: true at " +
                                                    number(any_lowest_true_) + " but false at " +
                                                    number(any_highest_false_));
  }

 private:
  const std::function<bool(double)>& predicate_;
  int max_evals_;
  ThresholdCache& known_;
  ThresholdResult r_;
  double lowest_true_ = std::numeric_limits<double>::infinity();
  double highest_false_ = -std::numeric_limits<double>::infinity();
  double any_lowest_true_ = lowest_true_, any_highest_false_ = highest_false_;
};

// Bracketing: step outward by the initial width until the result changes, down from lo while
// true (not below the floor) or up from hi while false (not above the ceiling). A result when the
// search ends here, nullopt once the bracket holds the threshold.
std::optional<ThresholdResult> bracket(ThresholdSearch& search, double lo, double hi, bool lo_true,
                                       bool hi_true, const ThresholdLimits& limits) {
  if (!lo_true && hi_true) return std::nullopt;
  const bool down = lo_true;
  const double limit = down ? limits.floor : limits.ceiling;
  const double step = down ? lo - hi : hi - lo;
  for (double v = down ? lo : hi;;) {
    if (down ? v <= limit : v >= limit)
      return search.finish(
          ThresholdStatus::NotBracketed,
          (down ? "true down to the floor " : "false up to the ceiling ") + number(v));
    v = down ? std::max(v + step, limit) : std::min(v + step, limit);
    const std::optional<bool> res = search.evaluate(v);
    if (!res)
      return search.finish(ThresholdStatus::NotBracketed,
                           down ? "evaluation limit reached stepping down, still true at " +
                                      number(search.lowest_true())
                                : "evaluation limit reached stepping up, still false at " +
                                      number(search.highest_false()));
    if (!search.monotone()) return search.non_monotone();
    if (*res != down) return std::nullopt;  // the first false going down, the first true going up
  }
}

// Bisection of (highest false, lowest true), or the guide's cuts.
ThresholdResult bisect(ThresholdSearch& search, double tol, const ThresholdGuide& guide) {
  Cutter cutter(guide, tol);
  while (search.width() > tol) {
    const double before = search.width();
    const std::optional<bool> res =
        search.evaluate(cutter.next(search.highest_false(), search.lowest_true()));
    if (!res)
      return search.finish(ThresholdStatus::EvaluationLimit,
                           "evaluation limit reached with bracket [" +
                               number(search.highest_false()) + ", " +
                               number(search.lowest_true()) + "]");
    if (!search.monotone()) return search.non_monotone();
    if (!(search.width() < before))  // a cache hit on a bracket end: no progress
      return search.finish(ThresholdStatus::EvaluationLimit, "bracket at the cache's resolution");
    cutter.narrowed(before, search.width());
  }
  return search.finish(ThresholdStatus::Found, "threshold in [" + number(search.highest_false()) +
                                                   ", " + number(search.lowest_true()) + "]");
}

}  // namespace

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
  ThresholdSearch search(predicate, max_evals, cache ? *cache : local);
  const bool lo_true = *search.evaluate(lo);
  if (!search.monotone()) return search.non_monotone();
  const bool hi_true = *search.evaluate(hi);
  if (!search.monotone()) return search.non_monotone();
  if (auto ended = bracket(search, lo, hi, lo_true, hi_true, limits)) return *ended;
  return bisect(search, tol, guide);
}

}  // namespace coldspray::studies
