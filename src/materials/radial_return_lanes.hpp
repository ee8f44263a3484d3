// consistent_return (radial_return.hpp) for four points at once, for flow stresses with a
// four-lane form (strength/ptw_lanes.hpp). It runs the common path in lock step: the yield check
// of a point that did not flow in the last step, or the secant steps from the last step's
// increment of one that did; one flow-stress evaluation per round serves all four lanes, and a
// lane stops where the scalar return would. A lane that needs more, a bracketed solve (a cold
// point that yields, or secant steps that leave the bracket or run out), is handed to the scalar
// return from the start, so every lane ends on the same tolerance: |f(x)| <= 1e-12 trial.
#pragma once

#include "core/simd.hpp"

#if COLDSPRAY_HAVE_SIMD

#include "materials/radial_return.hpp"

namespace coldspray::materials {

// Lane i: trial stress trial[i] > 0, 3G = three_G[i] > 0, guess[i] and slope[i] as for
// consistent_return.
// `flow(x)` gives the four lanes' flow stresses at increments x; `scalar_return(i)` is
// consistent_return of lane i alone.
template <class FlowLanes, class ScalarReturn>
COLDSPRAY_SIMD_TARGET void consistent_return_lanes(simd::Doubles trial, simd::Doubles three_G,
                                                   simd::Doubles guess, simd::Doubles slope,
                                                   FlowLanes&& flow, ScalarReturn&& scalar_return,
                                                   PlasticIncrement (&result)[simd::kLanes]) {
  using simd::Doubles;
  using simd::Mask;
  const Doubles zero = simd::broadcast(0.0);
  const Doubles tolerance = kReturnTolerance * trial;
  const Mask warm = (guess > 0.0) & (guess < trial / three_G);

  // The first evaluation: at the guess (warm lanes), or the yield check at 0 (cold lanes).
  Doubles x0 = warm ? guess : zero;
  const Doubles flow_first = flow(x0);
  const Doubles f_first = trial - three_G * x0 - flow_first;
  Doubles f0 = f_first;
  // The best evaluation so far of each warm lane, and the bracket f(a) > 0 >= f(b).
  Doubles best_x = x0, best_flow = flow_first, best_residual = simd::abs(f0);
  Mask yields = f0 > 0.0;
  Doubles a = yields ? x0 : zero;
  Doubles b = yields ? x0 + f0 / three_G : x0;
  Doubles evaluations = simd::broadcast(1.0);

  // Secant steps from the guess, each evaluation narrowing the bracket.
  // The second point as second_secant_point's.
  const Mask newton = (slope > three_G) & (slope < __builtin_inf());  // usable_slope
  const Doubles largest_offset = kSecantOffset * x0;
  Doubles x1 = newton
                   ? x0 + simd::max(f0 / slope, -0.5 * x0)
                   : x0 + simd::min(simd::max(0.5 * f0 / three_G, -largest_offset), largest_offset);
  for (;;) {
    const Mask active = warm & (best_residual > tolerance) & (evaluations < kSecantMaxEvaluations) &
                        (x1 > a) & (x1 < b);
    if (!simd::any(active)) break;
    const Doubles x = active ? x1 : x0;  // idle lanes evaluate a harmless point
    const Doubles flow_x = flow(x);
    const Doubles fx = trial - three_G * x - flow_x;
    const Mask better = active & (simd::abs(fx) < best_residual);
    best_x = better ? x : best_x;
    best_flow = better ? flow_x : best_flow;
    best_residual = better ? simd::abs(fx) : best_residual;
    const Mask above = active & (fx > 0.0);
    yields |= above;
    a = above ? x : a;
    b = (active & ~above) ? x : b;
    evaluations = active ? evaluations + 1.0 : evaluations;
    const Doubles x2 = x - fx * (x - x0) / (fx - f0);
    slope = (active & (x != x0)) ? -(fx - f0) / (x - x0) : slope;
    x0 = active ? x : x0;
    f0 = active ? fx : f0;
    x1 = active ? x2 : x1;
  }

  // As in the scalar return, a lane that converged yields; a cold lane's first evaluation was
  // its yield check.
  const Mask converged = warm & (best_residual <= tolerance);
  const Mask elastic = ~warm & (f_first <= 0.0);
  for (int i = 0; i < simd::kLanes; ++i) {
    const int n = static_cast<int>(evaluations[i]);
    if (elastic[i])
      result[i] = {0.0, flow_first[i], n, slope[i]};
    else if (converged[i])
      result[i] = {best_x[i], best_flow[i], n, slope[i]};
    else
      result[i] = scalar_return(i);
  }
}

}  // namespace coldspray::materials

#endif
