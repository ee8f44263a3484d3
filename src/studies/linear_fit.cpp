#include "studies/linear_fit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace coldspray::studies {

LinearFit fit_line(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_line: x and y differ in size");
  if (x.size() < 2) throw std::invalid_argument("fit_line: need at least two points");
  const std::size_t n = x.size();
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw std::invalid_argument("fit_line: non-finite data");
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - mx, dy = y[i] - my;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }
  if (!(sxx > 0.0)) throw std::invalid_argument("fit_line: all x are equal");

  LinearFit f;
  f.n = n;
  f.b = sxy / sxx;
  f.a = my - f.b * mx;
  double ss_res = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = y[i] - f(x[i]);
    ss_res += e * e;
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  f.r_squared = syy > 0.0 ? 1.0 - ss_res / syy : kNaN;
  if (n > 2) {
    const double s2 = ss_res / static_cast<double>(n - 2);
    f.residual_std = std::sqrt(s2);
    f.se_b = std::sqrt(s2 / sxx);
    f.se_a = std::sqrt(s2 * (1.0 / static_cast<double>(n) + mx * mx / sxx));
  } else {
    f.residual_std = f.se_a = f.se_b = kNaN;
  }
  return f;
}

}  // namespace coldspray::studies
