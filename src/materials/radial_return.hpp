// The consistent J2 return (thesis Appendix A, steps 5-7, with the flow stress solved within the
// step instead of eq A6's linearisation): find the plastic strain increment x >= 0 with
//   f(x) = trial - 3 G x - sigma_y(x) = 0,
// sigma_y(x) the flow stress at eqps^n + x and rate x/dt. sigma_y does not decrease with x
// (strain and rate hardening), so f decreases and the root is unique; it is bracketed by
// f(0) = trial - sigma_y(0) > 0 (the point yields) and x_max = (trial - sigma_y(0))/(3G), where
// f(x_max) = sigma_y(0) - sigma_y(x_max) <= 0. Anderson-Bjorck regula falsi on that bracket is
// exact in one step for linear hardening and superlinear for smooth flow stresses (PTW and
// Johnson-Cook from 1e3 to 1e9 1/s: 6-13 evaluations to 1e-12); a bisection step after four
// iterations that fail to halve the bracket bounds the work for anything rougher.
#pragma once

#include <cmath>

namespace coldspray::materials {

// Convergence: |f(x)| <= kReturnTolerance * trial, so the returned stress lies on the yield
// surface of its own final strain and rate, and satisfies the return, to 1e-12 relative.
inline constexpr double kReturnTolerance = 1e-12;
// Bound on flow-stress evaluations. With the forced bisections the bracket at least halves every
// five evaluations; smooth flow stresses converge in under 15, a discontinuous one collapses the
// bracket onto its jump in about 90.
inline constexpr int kReturnMaxEvaluations = 200;

struct PlasticIncrement {
  double eqps_increment = 0.0;  // x
  double flow_stress = 0.0;     // sigma_y(x)
  int evaluations = 0;          // of the flow stress
};

// `trial` is the trial von Mises stress, `three_G` = 3G > 0, `flow_at_zero` = sigma_y(0) <
// trial (the yield check's value), `flow(x)` the flow stress at the increment x.
template <class Flow>
PlasticIncrement solve_plastic_increment(double trial, double three_G, double flow_at_zero,
                                         Flow&& flow) {
  double a = 0.0;
  double fa = trial - flow_at_zero;
  double b = fa / three_G;
  const double flow_b = flow(b);
  double fb = flow_at_zero - flow_b;
  PlasticIncrement best{b, flow_b, 1};
  double best_residual = std::abs(fb);
  int side = 0;          // which end the last step moved: -1 a, +1 b, 0 after a bisection
  int stalled = 0;       // iterations since the bracket last halved
  double width = b - a;  // bracket width when it last halved
  while (best.evaluations < kReturnMaxEvaluations && best_residual > kReturnTolerance * trial) {
    const bool bisect = stalled >= 4;
    double x = bisect ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
    if (!(x > a && x < b)) x = 0.5 * (a + b);  // regula falsi rounded onto an end
    if (!(x > a && x < b)) break;              // the bracket is two adjacent doubles
    const double flow_x = flow(x);
    const double fx = trial - three_G * x - flow_x;
    ++best.evaluations;
    if (std::abs(fx) < best_residual) {
      best = {x, flow_x, best.evaluations};
      best_residual = std::abs(fx);
    }
    // Anderson-Bjorck: when the same end moves twice, scale the other end's value down.
    if (fx > 0.0) {
      if (side == -1) fb *= fx < fa ? 1.0 - fx / fa : 0.5;
      a = x;
      fa = fx;
      side = bisect ? 0 : -1;
    } else {
      if (side == +1) fa *= fx > fb ? 1.0 - fx / fb : 0.5;
      b = x;
      fb = fx;
      side = bisect ? 0 : +1;
    }
    if (b - a <= 0.5 * width) {
      width = b - a;
      stalled = 0;
    } else {
      ++stalled;
    }
  }
  return best;
}

}  // namespace coldspray::materials
