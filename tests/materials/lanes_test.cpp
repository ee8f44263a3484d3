// The four-lane forms of the constitutive update against their scalar originals: PtwLanes
// against PtwStep (and the hand-calculated al-ptw number of ptw_test.cpp), the lock-step return
// against consistent_return on every path (elastic, warm secant, cold yielding and
// non-converging lanes handed to the scalar return), the shear modulus and melt lanes against
// their scalar models, and update_points against update_point.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/simd.hpp"
#include "materials/model_dispatch.hpp"
#include "materials/stress_update_lanes.hpp"
#include "reference_materials.hpp"

#if COLDSPRAY_HAVE_SIMD

namespace coldspray::materials {
namespace {

using Lanes = std::array<double, simd::kLanes>;

const strength::Ptw& al_ptw_strength() {
  static const Material m = testing::al_ptw();
  return std::get<strength::Ptw>(m.strength);
}

COLDSPRAY_SIMD_TARGET Lanes ptw_lanes(const strength::Conditions (&c)[simd::kLanes],
                                      const Lanes& eqps, const Lanes& rate) {
  const strength::PtwLanes flow(al_ptw_strength(), c);
  const simd::Doubles y = flow(simd::Doubles{eqps[0], eqps[1], eqps[2], eqps[3]},
                               simd::Doubles{rate[0], rate[1], rate[2], rate[3]});
  return {y[0], y[1], y[2], y[3]};
}

// al-ptw's MTS shear modulus at 298 K (eq 2.6), as in ptw_test.cpp.
const double kMu298 = 28.8e9 - 3.44e9 / (std::exp(215.0 / 298.0) - 1.0);

TEST(MaterialsLanes, PtwLanesMatchesTheHandCalculation) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const strength::Conditions c{298.0, 2700.0, kMu298, 1220.0};
  const strength::Conditions cs[simd::kLanes] = {c, c, c, c};
  // eqps 0.5 at 1e7 1/s: 414.37439965328649e6 Pa (ptw_test.cpp); 0.02 at 1e3 and 1e5 1/s:
  // 112.517188132795e6 and 153.81130200251172e6 Pa; 1e10 1/s: 1.6888571488602318e9 Pa.
  const Lanes y = ptw_lanes(cs, {0.5, 0.02, 0.02, 0.5}, {1e7, 1e3, 1e5, 1e10});
  const Lanes hand = {414.37439965328649e6, 112.517188132795e6, 153.81130200251172e6,
                      1.6888571488602318e9};
  for (int l = 0; l < simd::kLanes; ++l) EXPECT_NEAR(y[l], hand[l], 1e-11 * hand[l]) << l;
}

// Lanes under different conditions, on every branch of eqs 2.4-2.7 and melted, each against
// PtwStep at the same point.
TEST(MaterialsLanes, PtwLanesMatchesPtwStepLaneByLane) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const strength::Ptw& p = al_ptw_strength();
  int compared = 0;
  for (double T : {298.0, 600.0, 1000.0, 1219.0, 1300.0})
    for (double rate : {0.0, 1e-3, 1e3, 1e5, 1e7, 1e9, 1e11})
      for (double eqps : {0.0, 1e-6, 0.02, 0.5, 3.0}) {
        const strength::Conditions cs[simd::kLanes] = {{T, 2700.0, 25e9, 1220.0},
                                                       {T, 2900.0, 27e9, 1350.0},
                                                       {298.0, 2700.0, kMu298, 1220.0},
                                                       {T, 2600.0, 20e9, 1100.0}};
        const Lanes eq = {eqps, 2.0 * eqps, 0.5, eqps}, r = {rate, rate, 1e4, 3.0 * rate};
        const Lanes y = ptw_lanes(cs, eq, r);
        for (int l = 0; l < simd::kLanes; ++l) {
          const double ref = strength::PtwStep(p, cs[l])(eq[l], r[l]);
          EXPECT_NEAR(y[l], ref, 1e-12 * std::abs(ref) + 1e-300)
              << "T " << T << " rate " << rate << " eqps " << eqps << " lane " << l;
          ++compared;
        }
      }
  EXPECT_EQ(compared, 5 * 7 * 5 * 4);
}

// One return problem per lane: al-ptw under conditions c, the trial stress, 3G, eqps^n, dt and
// the guess.
struct ReturnProblem {
  strength::Conditions c;
  double trial, three_G, eqps, dt, guess, slope;
};

COLDSPRAY_SIMD_TARGET std::array<PlasticIncrement, simd::kLanes> lanes_return(
    const ReturnProblem (&q)[simd::kLanes]) {
  strength::Conditions cs[simd::kLanes];
  simd::Doubles trial, three_G, guess, slope, eqps, dt;
  for (int l = 0; l < simd::kLanes; ++l) {
    cs[l] = q[l].c;
    trial[l] = q[l].trial;
    three_G[l] = q[l].three_G;
    guess[l] = q[l].guess;
    slope[l] = q[l].slope;
    eqps[l] = q[l].eqps;
    dt[l] = q[l].dt;
  }
  const strength::PtwLanes flow(al_ptw_strength(), cs);
  PlasticIncrement out[simd::kLanes];
  consistent_return_lanes(
      trial, three_G, guess, slope,
      [&](simd::Doubles x) COLDSPRAY_SIMD_TARGET { return flow(eqps + x, x / dt); },
      [&](int l) {
        const strength::PtwStep f(al_ptw_strength(), q[l].c);
        return consistent_return(q[l].trial, q[l].three_G, q[l].guess, q[l].slope,
                                 [&](double x) { return f(q[l].eqps + x, x / q[l].dt); });
      },
      out);
  return {out[0], out[1], out[2], out[3]};
}

// Across trial stresses from below yield to five times it, conditions from cold to melted,
// guesses from none to far off (and past the bracket) and last-step slopes from none, through
// the root's own, to unusable ones, every lane ends where the scalar return does: the same
// increment to within the solve's tolerance, the same elastic/plastic decision, and the same
// slope for the next step.
TEST(MaterialsLanes, LockStepReturnMatchesTheScalarReturn) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const strength::Ptw& p = al_ptw_strength();
  const double dt = 3e-11;
  std::vector<ReturnProblem> problems;
  for (double T : {298.0, 700.0, 1250.0})
    for (double trial : {50e6, 150e6, 300e6, 600e6, 1.5e9})
      for (double eqps : {0.0, 0.3, 2.0}) {
        const strength::Conditions c{T, 2750.0, 25e9, 1240.0};
        const double three_G = 3.0 * c.shear_modulus;
        const strength::PtwStep f(p, c);
        const PlasticIncrement exact = consistent_return(
            trial, three_G, 0.0, 0.0, [&](double x) { return f(eqps + x, x / dt); });
        for (double slope : {0.0, exact.residual_slope, 0.5 * three_G, 1e30, 1.0 / 0.0}) {
          for (double g : {0.0, 1.0, 1.01, 0.5, 10.0, 1e3})
            problems.push_back({c, trial, three_G, eqps, dt, g * exact.eqps_increment, slope});
          problems.push_back({c, trial, three_G, eqps, dt, 2.0 * trial / three_G, slope});
          problems.push_back({c, trial, three_G, eqps, dt, 1e-9 * dt, slope});  // yields at rest
        }
      }
  while (problems.size() % simd::kLanes != 0) problems.push_back(problems.back());

  int elastic = 0, plastic = 0;
  for (std::size_t i = 0; i < problems.size(); i += simd::kLanes) {
    const ReturnProblem q[simd::kLanes] = {problems[i], problems[i + 1], problems[i + 2],
                                           problems[i + 3]};
    const auto lanes = lanes_return(q);
    for (int l = 0; l < simd::kLanes; ++l) {
      const ReturnProblem& r = q[l];
      const strength::PtwStep f(p, r.c);
      const PlasticIncrement ref = consistent_return(
          r.trial, r.three_G, r.guess, r.slope, [&](double x) { return f(r.eqps + x, x / r.dt); });
      const double x = lanes[l].eqps_increment;
      EXPECT_EQ(x == 0.0, ref.eqps_increment == 0.0) << i + l;
      // The slope is a difference quotient of the last two, nearly equal, evaluations: the
      // vector functions' rounding moves it by up to 2e-4 here (it only starts the next return).
      if (std::isfinite(ref.residual_slope)) {
        EXPECT_NEAR(lanes[l].residual_slope, ref.residual_slope, 1e-3 * ref.residual_slope)
            << i + l;
      }
      EXPECT_NEAR(x, ref.eqps_increment, 1e-11 * r.trial / r.three_G) << i + l;
      EXPECT_NEAR(lanes[l].flow_stress, ref.flow_stress, 1e-11 * r.trial) << i + l;
      // On the yield surface of its own increment (or inside it, elastic).
      const double residual = r.trial - r.three_G * x - f(r.eqps + x, x / r.dt);
      if (x > 0.0)
        EXPECT_LE(std::abs(residual), 2e-12 * r.trial) << i + l;
      else
        EXPECT_LE(residual, 0.0) << i + l;
      (x > 0.0 ? plastic : elastic) += 1;
    }
  }
  EXPECT_GT(elastic, 10);
  EXPECT_GT(plastic, 100);
}

// update_points (four lanes) against update_point per point: the same stress, strain,
// temperature and energy to round-off, and partly plastic, partly elastic batches.
TEST(MaterialsLanes, BatchUpdateMatchesPointUpdates) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const Material m = testing::al_ptw();
  const UpdateOptions opt;
  int plastic = 0, elastic = 0;
  visit_models(m, [&](const auto& models) {
    PointState batch[kBatchPoints], single[kBatchPoints];
    for (int i = 0; i < kBatchPoints; ++i) batch[i] = single[i] = initial_point(models, 298.0);
    for (int step = 0; step < 40; ++step) {
      StepKinematics k[kBatchPoints];
      for (int i = 0; i < kBatchPoints; ++i) {
        // Elastic loading, then plastic.
        const double shear = (i + 1) * (step < 10 ? 1e-6 : 4e-4);
        k[i].strain_increment(0, 1) = k[i].strain_increment(1, 0) = shear;
        k[i].strain_increment(2, 2) = -1e-4 * i;
        k[i].spin_increment = {{1e-4, 0.0, 0.0}};  // W_xy = -W_yx
        k[i].dt = 2e-11;
        k[i].J_new = single[i].J * (1.0 - 1e-4 * i);
      }
      update_points(models, k, opt, batch);
      for (int i = 0; i < kBatchPoints; ++i) {
        const double eqps_before = single[i].eqps;
        update_point(models, k[i], opt, single[i]);
        (single[i].eqps > eqps_before ? plastic : elastic) += 1;
        const double scale = single[i].stress.matrix().norm();
        EXPECT_LE((batch[i].stress.matrix() - single[i].stress.matrix()).norm(), 1e-10 * scale)
            << step << " " << i;
        EXPECT_NEAR(batch[i].eqps, single[i].eqps, 1e-10 * single[i].eqps) << step << " " << i;
        EXPECT_NEAR(batch[i].temperature, single[i].temperature, 1e-9) << step << " " << i;
        EXPECT_NEAR(batch[i].energy, single[i].energy, 1e-9 * std::abs(single[i].energy))
            << step << " " << i;
      }
    }
  });
  EXPECT_GT(plastic, 50);
  EXPECT_GT(elastic, 10);
}

// The MTS shear modulus (eq 2.6) and the SCG melting temperature (eq 2.9) of four points at once
// against the scalar models, across the temperatures and compressions of an impact, and the
// floor of MTS at 1 % of mu0.
COLDSPRAY_SIMD_TARGET void expect_condition_lanes_match(const Material& m) {
  visit_models(m, [&](const auto& models) {
    for (double T0 : {50.0, 298.0, 700.0, 5000.0, 1e6}) {
      const simd::Doubles T = {T0, 1.5 * T0, 2.0 * T0, 3.0 * T0};
      const simd::Doubles G = shear_modulus_lanes(models, T);
      for (int l = 0; l < simd::kLanes; ++l) {
        const double scalar = models.shear_modulus_at(T[l]);
        EXPECT_NEAR(G[l], scalar, 1e-14 * scalar) << T[l];
      }
    }
    for (double eta : {0.8, 1.0, 1.2, 1.6}) {
      const simd::Doubles rho = simd::broadcast(m.density) * simd::Doubles{eta, 1.01, 0.99, 1.3};
      const simd::Doubles Tm = melt_temperature_lanes(models, rho);
      for (int l = 0; l < simd::kLanes; ++l) {
        const double scalar = models.melt_temperature_at(rho[l]);
        EXPECT_NEAR(Tm[l], scalar, 1e-14 * scalar) << rho[l];
      }
    }
  });
}

TEST(MaterialsLanes, ShearModulusAndMeltLanesMatchTheScalarModels) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const Material al = testing::al_ptw();  // MTS and SCG
  expect_condition_lanes_match(al);
  // The floor: far above T0 eq 2.6 falls below 1 % of mu0.
  visit_models(al,
               [](const auto& models) { EXPECT_EQ(models.shear_modulus_at(1e6), 0.01 * 28.8e9); });
  expect_condition_lanes_match(testing::cu_jc());  // constant models
}

// Every update leaves G at the state's new temperature, in the scalar and the batched form, so
// that the next step and the wave speed need not evaluate the model again.
TEST(MaterialsLanes, UpdatesKeepTheShearModulusAtTheNewTemperature) {
  if (!simd::available()) GTEST_SKIP() << "no AVX2 on this processor";
  const Material m = testing::al_ptw();
  visit_models(m, [&](const auto& models) {
    PointState batch[kBatchPoints], single = initial_point(models, 298.0);
    for (auto& b : batch) b = single;
    for (int step = 0; step < 30; ++step) {
      StepKinematics k[kBatchPoints];
      for (auto& ki : k) {
        ki.strain_increment(0, 1) = ki.strain_increment(1, 0) = 2e-3;
        ki.dt = 2e-11;
      }
      update_points(models, k, {}, batch);
      update_point(models, k[0], {}, single);
    }
    EXPECT_GT(single.temperature, 310.0);
    EXPECT_EQ(single.shear_modulus, models.shear_modulus_at(single.temperature));
    for (const auto& b : batch) {
      const double scalar = models.shear_modulus_at(b.temperature);
      EXPECT_NEAR(b.shear_modulus, scalar, 1e-14 * scalar);
    }
  });
}

}  // namespace
}  // namespace coldspray::materials

#endif
