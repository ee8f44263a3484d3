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
// A point that flowed in the last step usually flows at a similar rate in this one: given that
// step's increment as a guess, secant steps from it (each evaluation also narrowing the bracket)
// reach the same tolerance in 5.1 evaluations instead of 8.6 (al-ptw, 3D impact benchmark); a
// secant step that leaves the bracket hands over to the regula falsi on what is left of it.
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

// Offset of the second secant point from the guess, relative: small enough that the first
// secant step is nearly a Newton step from the guess, large enough that the secant slope is
// not rounding noise.
inline constexpr double kSecantOffset = 0.02;
// Secant evaluations before the bracketed solve takes over.
inline constexpr int kSecantMaxEvaluations = 8;

// `trial` is the trial von Mises stress, `three_G` = 3G > 0, `flow_at_zero` = sigma_y(0) <
// trial (the yield check's value), `flow(x)` the flow stress at the increment x, `guess` an
// estimate of x (0 for none).
template <class Flow>
PlasticIncrement solve_plastic_increment(double trial, double three_G, double flow_at_zero,
                                         double guess, Flow&& flow) {
  const double tolerance = kReturnTolerance * trial;
  double a = 0.0;
  double fa = trial - flow_at_zero;
  double b = fa / three_G;
  double fb = 0.0;  // f(x_max) <= 0 is known without evaluating it; its value is not
  bool fb_known = false;
  PlasticIncrement best;
  double best_residual = 0.0;
  // Counts an evaluation f(x) = fx, with flow_x = sigma_y(x), and keeps the best so far.
  auto record = [&](double x, double flow_x, double fx) {
    ++best.evaluations;
    if (best.evaluations == 1 || std::abs(fx) < best_residual) {
      best = {x, flow_x, best.evaluations};
      best_residual = std::abs(fx);
    }
  };

  // Secant steps from the guess, each evaluation narrowing the bracket.
  if (guess > a && guess < b) {
    auto evaluate = [&](double x) {
      const double flow_x = flow(x);
      const double fx = trial - three_G * x - flow_x;
      record(x, flow_x, fx);
      if (fx > 0.0) {
        a = x;
        fa = fx;
      } else {
        b = x;
        fb = fx;
        fb_known = true;
      }
      return fx;
    };
    double x0 = guess;
    double f0 = evaluate(x0);
    // The second point on the side of the root.
    double x1 = x0 * (f0 > 0.0 ? 1.0 + kSecantOffset : 1.0 - kSecantOffset);
    while (best_residual > tolerance && best.evaluations < kSecantMaxEvaluations && x1 > a &&
           x1 < b) {
      const double f1 = evaluate(x1);
      const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
      x0 = x1;
      f0 = f1;
      x1 = x2;
    }
  }
  if (!fb_known && (best.evaluations == 0 || best_residual > tolerance)) {
    const double flow_b = flow(b);
    fb = flow_at_zero - flow_b;
    record(b, flow_b, fb);
  }

  // Anderson-Bjorck regula falsi on [a, b].
  int side = 0;          // which end the last step moved: -1 a, +1 b, 0 after a bisection
  int stalled = 0;       // iterations since the bracket last halved
  double width = b - a;  // bracket width when it last halved
  while (best.evaluations < kReturnMaxEvaluations && best_residual > tolerance) {
    const bool bisect = stalled >= 4;
    double x = bisect ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
    if (!(x > a && x < b)) x = 0.5 * (a + b);  // regula falsi rounded onto an end
    if (!(x > a && x < b)) break;              // the bracket is two adjacent doubles
    const double flow_x = flow(x);
    const double fx = trial - three_G * x - flow_x;
    record(x, flow_x, fx);
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
