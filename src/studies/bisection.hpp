// The threshold of a monotone yes/no outcome: the lowest value at which an expensive predicate
// turns true, by bracketing and bisection. The thesis finds a particle size's critical velocity
// as the lowest impact velocity that bonds (mpm-bonding-thesis.md §5.2.2, Table 5.4); here the
// predicate is "an impact at v bonds". Pure math; see docs/studies-math.md.
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coldspray::studies {

// Results of a predicate by value, shared between searches so that a value already simulated is
// never simulated again. Two values are the same when they differ by at most 1e-9 relative
// (|a - b| <= 1e-9 max(|a|, |b|)).
class ThresholdCache {
 public:
  static constexpr double kRelativeTolerance = 1e-9;
  // The stored (value, result) that matches `value`, if any.
  std::optional<std::pair<double, bool>> find(double value) const;
  void insert(double value, bool result);  // replaces the result of the same value
  std::size_t size() const { return results_.size(); }
  const std::map<double, bool>& results() const { return results_; }

 private:
  std::map<double, bool> results_;
};

enum class ThresholdStatus {
  Found,            // bracket [lower, upper] with upper - lower <= tol; threshold = upper
  NotBracketed,     // no false value below a true one: true down to the floor, false up to the
                    // ceiling, or the evaluation budget spent while stepping outward
  EvaluationLimit,  // bracketed, but max_evals spent before the bracket reached tol
  NonMonotone,      // a true result at a value below a false result: see `conflict`
};
std::string to_string(ThresholdStatus s);

struct ThresholdEvaluation {
  double value = 0.0;
  bool result = false;
  bool cached = false;  // taken from the cache, the predicate was not called
};

// The outer limits of the bracketing steps (e.g. floor 0 for a velocity).
struct ThresholdLimits {
  double floor = -std::numeric_limits<double>::infinity();
  double ceiling = std::numeric_limits<double>::infinity();
};

struct ThresholdResult {
  ThresholdStatus status = ThresholdStatus::NotBracketed;
  // The lowest value found true (NaN if none): the threshold estimate, within tol above the
  // true threshold when Found.
  double threshold = std::numeric_limits<double>::quiet_NaN();
  double lower = std::numeric_limits<double>::quiet_NaN();  // highest false below `threshold`
  double upper = std::numeric_limits<double>::quiet_NaN();  // = threshold
  std::vector<ThresholdEvaluation> evaluations;             // in order, cached ones included
  int predicate_calls = 0;                                  // evaluations not from the cache
  // For NonMonotone: the lowest value known true and the highest known false, above it.
  std::optional<std::pair<double, double>> conflict;  // (true value, false value), true < false
  std::string message;                                // one line saying what happened

  bool found() const { return status == ThresholdStatus::Found; }
};

// A guess of the threshold inside the bracket (highest false, lowest true), from what the
// evaluations at its ends measured besides their result (the impacts' penetration, for vcrit);
// NaN for none, and the bisection takes the midpoint.
using ThresholdGuide = std::function<double(double highest_false, double lowest_true)>;

// The threshold of a predicate that is false below it and true above. Evaluates lo and hi;
// if lo is true, steps down by (hi - lo) (not below limits.floor) until a value is false; if hi
// is false, steps up by (hi - lo) (not above limits.ceiling) until one is true; then bisects the
// bracket (highest false, lowest true) until its width <= tol. Values already in `cache` (within
// 1e-9 relative) are not evaluated again, and every new result is added to it; pass nullptr for
// a cache local to this call; a cache hit is recorded at the stored value. max_evals bounds the
// predicate calls (cache hits are free). After
// each result the search checks every result known for the predicate, its own and the cache's:
// a true at a value below a false stops it with status NonMonotone. (Bisection only samples
// inside the bracket, so a conflict shows up through lo and hi, the stepping, or the cache: an
// exception confined to a narrow window the search never samples cannot be seen.) Throws
// std::invalid_argument unless lo < hi, tol >= 1e-8 max(|lo|, |hi|) (coarser than the cache's
// resolution), max_evals >= 2 and floor <= lo, hi <= ceiling. With a `guide`, the bracket is
// cut at its guess (regula falsi on a measured margin), kept min(0.4 tol, a quarter of the
// bracket) inside its ends so that every evaluation narrows it; after two guided cuts in a row
// that kept more than half of it, one midpoint cut (the safeguard of the Illinois and Dekker
// methods against a guess that creeps up on one end).
ThresholdResult find_threshold(const std::function<bool(double)>& predicate, double lo, double hi,
                               double tol, int max_evals, ThresholdCache* cache = nullptr,
                               const ThresholdLimits& limits = {},
                               const ThresholdGuide& guide = {});

}  // namespace coldspray::studies
