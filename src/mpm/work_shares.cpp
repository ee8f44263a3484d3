#include "mpm/work_shares.hpp"

#include <algorithm>
#include <cmath>

namespace coldspray::mpm {

void WorkShares::prepare(int shares, std::size_t items) {
  const auto n = static_cast<std::size_t>(std::max(shares, 1));
  if (first_.size() == n + 1 && first_.back() == items) return;
  first_.resize(n + 1);
  for (std::size_t k = 0; k <= n; ++k) first_[k] = items * k / n;
  seconds_.assign(n, 0.0);
  target_.assign(n + 1, 0);
}

void WorkShares::rebalance() {
  const std::size_t n = seconds_.size();
  double total = 0.0;
  for (const double t : seconds_) total += t;
  if (n < 2 || !(total > 0.0)) return;
  // The cost up to item i is piecewise linear in i, with share k's time spread evenly over its
  // range; boundary j goes where that cost reaches j/n of the total.
  std::size_t k = 0;
  double before = 0.0;  // the time of the shares before k
  for (std::size_t j = 1; j < n; ++j) {
    const double goal = total * static_cast<double>(j) / static_cast<double>(n);
    while (k + 1 < n && before + seconds_[k] < goal) before += seconds_[k++];
    const double width = static_cast<double>(first_[k + 1] - first_[k]);
    const double fraction = seconds_[k] > 0.0 ? std::min((goal - before) / seconds_[k], 1.0) : 0.0;
    target_[j] = first_[k] + static_cast<std::size_t>(std::llround(width * fraction));
  }
  // Halfway: a range's cost is not uniform, and a step's timings are noisy.
  for (std::size_t j = 1; j < n; ++j) first_[j] = (first_[j] + target_[j]) / 2;
}

}  // namespace coldspray::mpm
