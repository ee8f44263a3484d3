// Least-squares straight line y = a + b x, e.g. the critical velocity against particle diameter,
// vcrit = a + b d (mpm-bonding-thesis.md §5.2.2, Table 5.4, Figure 5.14). Pure math; see
// docs/studies-math.md.
#pragma once

#include <cstddef>
#include <span>

namespace coldspray::studies {

struct LinearFit {
  double a = 0.0;  // intercept
  double b = 0.0;  // slope
  // Coefficient of determination 1 - SS_res / SS_tot; NaN when all y are equal (SS_tot = 0).
  double r_squared = 0.0;
  // Standard errors of a and b from the residual variance s^2 = SS_res / (n - 2); NaN for n = 2.
  double se_a = 0.0;
  double se_b = 0.0;
  double residual_std = 0.0;  // s
  std::size_t n = 0;

  double operator()(double x) const { return a + b * x; }
};

// Ordinary least squares of y on x (centred sums). Throws std::invalid_argument unless x and y
// have the same size >= 2, are finite, and x holds at least two distinct values.
LinearFit fit_line(std::span<const double> x, std::span<const double> y);

}  // namespace coldspray::studies
