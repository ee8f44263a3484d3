// update_point (stress_update_kernel.hpp) for a batch of four points, for solvers that loop over
// arrays of points. Where the strength model has a four-lane flow stress (PTW) and the processor
// runs AVX2, the four returns are solved together (radial_return_lanes.hpp), and so are the melt
// temperatures before them and the shear moduli after (condition_lanes.hpp); the rest of the
// steps stays per point. Otherwise each point takes update_point.
#pragma once

#include "core/simd.hpp"
#include "materials/stress_update_kernel.hpp"

#if COLDSPRAY_HAVE_SIMD
#include "materials/condition_lanes.hpp"
#include "materials/radial_return_lanes.hpp"
#include "materials/strength/ptw_lanes.hpp"
#endif

namespace coldspray::materials {

inline constexpr int kBatchPoints = 4;

#if COLDSPRAY_HAVE_SIMD
static_assert(kBatchPoints == simd::kLanes);

// Whether the strength model of Models has a four-lane form.
template <class Models>
concept HasFlowLanes = requires(const Models& m, const strength::Conditions (&c)[simd::kLanes]) {
  strength::prepare_lanes(m.strength_model, c);
};

template <class Models>
COLDSPRAY_SIMD_TARGET void update_lanes(const Models& models,
                                        const StepKinematics (&k)[kBatchPoints],
                                        const UpdateOptions& opt, PointState (&st)[kBatchPoints]) {
  simd::Doubles density;
  for (int i = 0; i < kBatchPoints; ++i) density[i] = step_density(models, k[i]);
  const simd::Doubles melt_temperature = melt_temperature_lanes(models, density);
  ElasticTrial t[kBatchPoints];
  strength::Conditions conditions[kBatchPoints];
  simd::Doubles trial, three_G, guess, slope, eqps, dt;
  for (int i = 0; i < kBatchPoints; ++i) {
    t[i] = elastic_trial(models, k[i], st[i], melt_temperature[i]);
    conditions[i] = t[i].conditions;
    trial[i] = t[i].trial;
    three_G[i] = t[i].three_G;
    guess[i] = warm_start(k[i], t[i], st[i]);
    slope[i] = st[i].return_slope;
    eqps[i] = st[i].eqps;
    dt[i] = k[i].dt;
  }
  const auto flow_stress = strength::prepare_lanes(models.strength_model, conditions);
  PlasticIncrement inc[kBatchPoints];
  consistent_return_lanes(
      trial, three_G, guess, slope,
      [&](simd::Doubles x) COLDSPRAY_SIMD_TARGET { return flow_stress(eqps + x, x / dt); },
      [&](int i) { return plastic_increment(models, k[i], t[i], st[i]); }, inc);
  simd::Doubles temperature;
  for (int i = 0; i < kBatchPoints; ++i) {
    complete_update(models, k[i], opt, t[i], inc[i], st[i]);
    temperature[i] = st[i].temperature;
  }
  // G at T^{n+1}, for the wave speed and the next step.
  const simd::Doubles G = shear_modulus_lanes(models, temperature);
  for (int i = 0; i < kBatchPoints; ++i) st[i].shear_modulus = G[i];
  // Clear the upper halves of the vector registers before the scalar code: left set, they slow
  // every SSE instruction after them (measured: the next step's particle-to-grid mapping took
  // twice as long).
  __builtin_ia32_vzeroupper();
}
#endif

// update_point of each of four points.
template <class Models>
void update_points(const Models& models, const StepKinematics (&k)[kBatchPoints],
                   const UpdateOptions& opt, PointState (&st)[kBatchPoints]) {
#if COLDSPRAY_HAVE_SIMD
  if constexpr (HasFlowLanes<Models>) {
    if (simd::available()) {
      update_lanes(models, k, opt, st);
      return;
    }
  }
#endif
  for (int i = 0; i < kBatchPoints; ++i) update_point(models, k[i], opt, st[i]);
}

}  // namespace coldspray::materials
