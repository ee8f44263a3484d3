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
// step's increment as a guess x0, secant steps from x0 (each evaluation also narrowing the
// bracket) reach the same tolerance in 5.1 evaluations in all instead of 9.6 (al-ptw, 3D impact
// benchmark). The slope of f near the last step's root (returned in residual_slope and kept
// with the point) makes both starting points Newton steps, predicted_increment and
// second_secant_point: 4.1 evaluations instead of 5.5 for a warm four-point batch's lanes
// (docs/materials.md). Any f(x) > 0 on the way shows that the point yields (f decreases), and so
// does convergence to a root x > 0, so the yield check is evaluated only if neither does; f(x0) > 0
// also brackets the root by [x0, x0 + f(x0)/(3G)]. A secant step that leaves the bracket hands
// over to the regula falsi on what is left of it.
#pragma once

#include <algorithm>
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
  // -df/dx = 3G + d sigma_y/dx between the return's last two evaluations, Pa: the next step's
  // Newton slope (the slope the return was given where it evaluated f fewer than twice).
  double residual_slope = 0.0;
};

// Whether a slope s from the last step can serve a Newton step: f falls at least as fast as
// -3G x, so a usable s exceeds 3G (0, rounding noise and a non-finite s do not).
inline bool usable_slope(double s, double three_G) { return s > three_G && std::isfinite(s); }

// The starting point of a point that flowed in the last step by last_increment, ending on
// last_flow_stress with slope -df/dx = s there: the root of f linearised about that end,
// x0 = x^n + (trial - 3G x^n - sigma_y^n)/s (flow stress advanced by d sigma_y/dx = s - 3G),
// kept within a factor of two of x^n. Without a usable slope: x^n.
inline double predicted_increment(double trial, double three_G, double last_increment,
                                  double last_flow_stress, double s) {
  if (!(last_increment > 0.0) || !usable_slope(s, three_G)) return last_increment;
  const double x0 = last_increment + (trial - three_G * last_increment - last_flow_stress) / s;
  return std::clamp(x0, 0.5 * last_increment, 2.0 * last_increment);
}

// Largest offset of the second secant point from the guess, relative: small enough that the
// first secant step is nearly a Newton step from the guess, large enough that the secant slope is
// not rounding noise.
inline constexpr double kSecantOffset = 0.02;

// The second secant point, from the guess x0, f0 = f(x0) and the last step's slope s. With a
// usable s, a Newton step, kept above x0/2 (f0 < 0 steps down, towards a = 0). Otherwise: as f
// decreases at least as fast as -3G x, the root lies between x0 and x0 + f0/(3G) (the end of the
// bracket on that side), and half that step stays inside the bracket: a guess that was already
// close (in an impact, most warm points) gets a second point as close, where a fixed offset would
// overshoot the bracket.
inline double second_secant_point(double x0, double f0, double three_G, double s) {
  if (usable_slope(s, three_G)) return x0 + std::max(f0 / s, -0.5 * x0);
  return x0 + std::clamp(0.5 * f0 / three_G, -kSecantOffset * x0, kSecantOffset * x0);
}
// Secant evaluations before the bracketed solve takes over.
inline constexpr int kSecantMaxEvaluations = 8;

// The state of one return: the best evaluation so far, the last one (for the slope) and the
// bracket [a, b] with f(a) > 0 >= f(b). Its upper end is first placed at b = x + f(x)/(3G) from
// a point x that yields, where f(b) = sigma_y(x) - sigma_y(b) <= 0 before it is evaluated.
struct ReturnState {
  double trial = 0.0, three_G = 0.0, tolerance = 0.0;
  double slope = 0.0;  // the last step's residual_slope, then the latest secant slope
  PlasticIncrement best;
  double best_residual = 0.0;
  // The last evaluation, for the slope between it and the next.
  double last_x = 0.0, last_f = 0.0;
  bool evaluated = false;
  double a = 0.0, fa = 0.0, b = 0.0, fb = 0.0;
  double flow_below_b = 0.0;  // sigma_y(x) of the point b was placed from
  bool fb_known = false;
  bool yields = false;  // some f(x) > 0 seen: then f(0) > 0 too, f decreases

  void track_slope(double x, double fx) {
    if (evaluated && x != last_x) slope = -(fx - last_f) / (x - last_x);
    last_x = x;
    last_f = fx;
    evaluated = true;
  }
  PlasticIncrement result() {
    best.residual_slope = slope;
    return best;
  }
  // Counts an evaluation f(x) = fx at x > 0, with flow_x = sigma_y(x), and keeps the best.
  void record(double x, double flow_x, double fx) {
    ++best.evaluations;
    track_slope(x, fx);
    if (best.eqps_increment == 0.0 || std::abs(fx) < best_residual) {
      best = {x, flow_x, best.evaluations};
      best_residual = std::abs(fx);
    }
  }
  void narrow(double x, double fx) {
    if (fx > 0.0) {
      a = x;
      fa = fx;
      yields = true;
    } else {
      b = x;
      fb = fx;
      fb_known = true;
    }
  }
};

// The yield check, f(0) > 0 (at eqps^n and the rate floor); its f(0) and sigma_y(0) are the
// bracket's lower end and the base of b = x_max.
template <class Flow>
bool yields_at_rest(ReturnState& r, Flow&& flow) {
  const double flow_0 = flow(0.0);
  ++r.best.evaluations;
  r.fa = r.trial - flow_0;
  r.track_slope(0.0, r.fa);
  r.flow_below_b = flow_0;
  r.yields = r.fa > 0.0;
  if (!r.yields) r.best = {0.0, flow_0, r.best.evaluations};
  return r.yields;
}

// Secant steps from the guess x0, each evaluation narrowing the bracket.
template <class Flow>
void secant_steps(ReturnState& r, double x0, Flow&& flow) {
  const double flow_0 = flow(x0);
  double f0 = r.trial - r.three_G * x0 - flow_0;
  r.record(x0, flow_0, f0);
  r.narrow(x0, f0);
  if (f0 > 0.0) {
    r.b = x0 + f0 / r.three_G;
    r.flow_below_b = flow_0;
  }
  double x1 = second_secant_point(x0, f0, r.three_G, r.slope);
  while (r.best_residual > r.tolerance && r.best.evaluations < kSecantMaxEvaluations && x1 > r.a &&
         x1 < r.b) {
    const double flow_1 = flow(x1);
    const double f1 = r.trial - r.three_G * x1 - flow_1;
    r.record(x1, flow_1, f1);
    r.narrow(x1, f1);
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1;
    f0 = f1;
    x1 = x2;
  }
}

// Anderson-Bjorck regula falsi on [a, b], until converged or out of evaluations.
template <class Flow>
void regula_falsi(ReturnState& r, Flow&& flow) {
  int side = 0;              // which end the last step moved: -1 a, +1 b, 0 after a bisection
  int stalled = 0;           // iterations since the bracket last halved
  double width = r.b - r.a;  // bracket width when it last halved
  while (r.best.evaluations < kReturnMaxEvaluations && r.best_residual > r.tolerance) {
    const bool bisect = stalled >= 4;
    double x = bisect ? 0.5 * (r.a + r.b) : (r.a * r.fb - r.b * r.fa) / (r.fb - r.fa);
    if (!(x > r.a && x < r.b)) x = 0.5 * (r.a + r.b);  // regula falsi rounded onto an end
    if (!(x > r.a && x < r.b)) break;                  // the bracket is two adjacent doubles
    const double flow_x = flow(x);
    const double fx = r.trial - r.three_G * x - flow_x;
    r.record(x, flow_x, fx);
    // Anderson-Bjorck: when the same end moves twice, scale the other end's value down.
    if (fx > 0.0) {
      if (side == -1) r.fb *= fx < r.fa ? 1.0 - fx / r.fa : 0.5;
      r.a = x;
      r.fa = fx;
      side = bisect ? 0 : -1;
    } else {
      if (side == +1) r.fa *= fx > r.fb ? 1.0 - fx / r.fb : 0.5;
      r.b = x;
      r.fb = fx;
      side = bisect ? 0 : +1;
    }
    if (r.b - r.a <= 0.5 * width) {
      width = r.b - r.a;
      stalled = 0;
    } else {
      ++stalled;
    }
  }
}

// The return of a point with trial von Mises stress `trial` > 0 and `three_G` = 3G > 0, where
// `flow(x)` is the flow stress at the increment x (flow(0): at eqps^n and the rate floor),
// `guess` an estimate of x (0 for none) and `slope` the last step's residual_slope (0 for none).
// Returns x = 0 and flow(0) where the point does not yield (f(0) <= 0), else the root of f;
// `evaluations` counts the yield check too.
template <class Flow>
PlasticIncrement consistent_return(double trial, double three_G, double guess, double slope,
                                   Flow&& flow) {
  ReturnState r;
  r.trial = trial;
  r.three_G = three_G;
  r.tolerance = kReturnTolerance * trial;
  r.slope = slope;
  if (guess > 0.0 && guess < trial / three_G) {
    secant_steps(r, guess, flow);
    // No step showed that the point yields: unless the secant steps converged, the yield check
    // decides (a = 0 gets its f). A converged x > 0 needs none: f decreases, so
    // f(0) >= f(x) >= -tolerance, and the point yields or is within the tolerance of yielding,
    // where x <= tolerance/(3G) is below what the solve resolves anyway.
    if (!r.yields && r.best_residual > r.tolerance && !yields_at_rest(r, flow)) return r.result();
  } else {
    if (!yields_at_rest(r, flow)) return r.result();
    r.b = r.fa / three_G;  // x_max
  }
  if (!r.fb_known && (r.best.eqps_increment == 0.0 || r.best_residual > r.tolerance)) {
    const double flow_b = flow(r.b);
    r.fb = r.flow_below_b - flow_b;
    r.record(r.b, flow_b, r.fb);
  }
  regula_falsi(r, flow);
  return r.result();
}

}  // namespace coldspray::materials
