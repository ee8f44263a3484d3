// The stress update (thesis Appendix A) checked through invariants and closed-form responses.
#include "materials/stress_update.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "materials/flow_stress.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const Matrix3d kI = Matrix3d::Identity();

Matrix3d deviator(const Matrix3d& a) { return a - a.trace() / 3.0 * kI; }
double von_mises_of(const Matrix3d& sigma) {
  const Matrix3d s = deviator(sigma);
  return std::sqrt(1.5 * (s.array() * s.array()).sum());
}
Matrix3d skew(const Vector3d& n) {
  Matrix3d k;
  k << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
  return k;
}
double mts_al(double T) { return 28.8e9 - 3.44e9 / (std::exp(215.0 / T) - 1.0); }
// Al Mie-Gruneisen reference pressure (validation-data.md §4), compression branch.
double al_A(double J) {
  const double mu = 1.0 / J - 1.0;
  return 2700.0 * 5386.0 * 5386.0 * mu * (1.0 + (1.0 - 1.97 / 2.0) * mu) /
         std::pow(1.0 - 0.339 * mu, 2);
}

// A deviator and a compressed state consistent with the EOS (J = 0.98, E = 0), so that a pure
// rotation leaves the pressure where it is.
PointState stressed_al_state(const Material& m) {
  PointState st = initial_state(m, 298.0);
  Matrix3d s;
  s << 100, 30, -20, 30, -40, 10, -20, 10, -60;
  st.J = 0.98;
  st.stress = SymmetricTensor::of(1e6 * s - al_A(0.98) * kI);
  st.pressure = al_A(0.98);
  return st;
}

StepKinematics spin_step(const Matrix3d& W) {
  StepKinematics k;
  k.spin_increment = SkewTensor::of(W);
  k.dt = 1e-9;
  k.J_new = 0.98;
  return k;
}

// One step of pure spin W dt = h K reproduces R sigma R^T, R = exp(h K), up to a residual of
// second order in h: the residual is at most 2 h^2 |s| and quarters when h halves.
TEST(MaterialsStressUpdate, RotationIsObjectiveToSecondOrder) {
  const Material m = testing::al_elastic();
  const PointState start = stressed_al_state(m);
  const Vector3d axis = Vector3d(1, 2, 3).normalized();
  const double s_norm = deviator(start.stress.matrix()).norm();
  double residual[2];
  for (int i = 0; i < 2; ++i) {
    const double h = 1e-3 / (1 << i);
    PointState st = start;
    update_stress(m, spin_step(h * skew(axis)), {}, st);
    const Matrix3d R = Eigen::AngleAxisd(h, axis).toRotationMatrix();
    residual[i] = (st.stress.matrix() - R * start.stress.matrix() * R.transpose()).norm();
    EXPECT_LE(residual[i], 2.0 * h * h * s_norm);
    // First order is right: the rotation itself is ~h |s|, far above the residual.
    EXPECT_GT((st.stress.matrix() - start.stress.matrix()).norm(), 0.5 * h * s_norm);
  }
  EXPECT_NEAR(residual[0] / residual[1], 4.0, 0.05);
}

// 40000 steps of 2.5e-8 rad about a fixed axis (1e-3 rad in all): pressure is untouched, the
// von Mises stress drifts by at most sum |[W, s]|^2/(2|s|^2) <= 2 N h^2 = 5e-11 relative, and the
// end state is R sigma R^T to O(N h^2).
TEST(MaterialsStressUpdate, ManySmallRotationsPreserveInvariants) {
  const Material m = testing::al_elastic();
  PointState st = stressed_al_state(m);
  const Matrix3d start = st.stress.matrix();
  const Vector3d axis = Vector3d(1, 2, 3).normalized();
  const int steps = 40000;
  const double h = 2.5e-8;
  const StepKinematics k = spin_step(h * skew(axis));
  for (int n = 0; n < steps; ++n) update_stress(m, k, {}, st);
  const double p0 = al_A(0.98);
  EXPECT_NEAR(st.pressure, p0, 1e-14 * p0);
  EXPECT_NEAR(-st.stress.matrix().trace() / 3.0, p0, 1e-14 * p0);
  const double vm0 = von_mises_of(start);
  EXPECT_NEAR(von_mises_of(st.stress.matrix()), vm0, 1e-10 * vm0);
  const Matrix3d R = Eigen::AngleAxisd(steps * h, axis).toRotationMatrix();
  EXPECT_LE((st.stress.matrix() - R * start * R.transpose()).norm(), 1e-9 * deviator(start).norm());
  EXPECT_GT((st.stress.matrix() - start).norm(), 1e-4 * deviator(start).norm());  // it did rotate
}

// Plastic steps land on the yield surface of their own final strain and rate, and satisfy the
// consistency condition sigma_vm = trial - 3 G d_eqps of the radial return, with the trial
// computed here from the previous state. PTW (al-ptw) over a range of rates, with heating.
TEST(MaterialsStressUpdate, ReturnLandsOnYieldSurfacePtw) {
  const Material m = testing::al_ptw();
  PointState st = initial_state(m, 298.0);
  int plastic_steps = 0;
  for (int n = 0; n < 60; ++n) {
    const double dt = std::pow(10.0, -4.0 - 0.1 * n);  // rates from ~1e1 to ~1e8 1/s
    Matrix3d d = Matrix3d::Zero();
    d(0, 1) = d(1, 0) = 2e-3;
    d(0, 0) = -1e-3;
    d(1, 1) = 4e-4;
    StepKinematics k;
    k.strain_increment = SymmetricTensor::of(d);
    k.dt = dt;
    k.J_new = st.J * std::exp(d.trace());
    const PointState before = st;
    update_stress(m, k, {}, st);
    const double rho = 2700.0 / k.J_new;
    const double G = mts_al(before.temperature);
    const Matrix3d s_trial = deviator(before.stress.matrix()) + 2.0 * G * deviator(d);
    const double trial = std::sqrt(1.5 * (s_trial.array() * s_trial.array()).sum());
    const double d_eqps = st.eqps - before.eqps;
    const double vm = von_mises_of(st.stress.matrix());
    if (d_eqps == 0.0) {
      EXPECT_NEAR(vm, trial, 1e-12 * trial);
      continue;
    }
    ++plastic_steps;
    EXPECT_NEAR(st.eqps_rate, d_eqps / dt, 1e-15 * st.eqps / dt);  // roundoff of the difference
    EXPECT_NEAR(vm, st.flow_stress, 1e-12 * vm) << n;
    const double expected_flow = flow_stress(m, st.eqps, st.eqps_rate, before.temperature, rho);
    EXPECT_NEAR(st.flow_stress, expected_flow, 1e-12 * vm) << n;
    EXPECT_NEAR(vm, trial - 3.0 * G * d_eqps, 1e-10 * trial) << n;
    EXPECT_NEAR((deviator(st.stress.matrix()) / vm - s_trial / trial).norm(), 0.0, 1e-12) << n;
    EXPECT_GT(st.temperature, before.temperature);
  }
  EXPECT_GT(plastic_steps, 50);
}

// The solver keeps no pressure per point: it outputs the stress's mean (mean_pressure). That is
// the update's EOS pressure, as the returned deviator is traceless, through compression, shear
// and flow.
TEST(MaterialsStressUpdate, StressMeanIsTheEosPressure) {
  const Material m = testing::al_ptw();
  PointState st = initial_state(m, 298.0);
  for (int n = 0; n < 40; ++n) {
    Matrix3d d = Matrix3d::Zero();
    d(0, 1) = d(1, 0) = 1.5e-3;
    d(2, 2) = -2e-3;
    StepKinematics k;
    k.strain_increment = SymmetricTensor::of(d);
    k.dt = 1e-9;
    k.J_new = st.J * std::exp(d.trace());
    update_stress(m, k, {}, st);
    ASSERT_GT(st.pressure, 0.0);
    EXPECT_NEAR(mean_pressure(st.stress), st.pressure,
                1e-14 * (st.pressure + st.stress.von_mises()))
        << n;
  }
  EXPECT_GT(st.eqps, 0.0);
}

// The same for Johnson-Cook copper (rate and temperature dependent, rate* floored at 1).
TEST(MaterialsStressUpdate, ReturnLandsOnYieldSurfaceJohnsonCook) {
  const Material m = testing::cu_jc();
  PointState st = initial_state(m, 298.0);
  for (int n = 0; n < 40; ++n) {
    const double dt = std::pow(10.0, -2.0 - 0.2 * n);
    Matrix3d d = Matrix3d::Zero();
    d(0, 2) = d(2, 0) = 1.5e-3;
    StepKinematics k;
    k.strain_increment = SymmetricTensor::of(d);
    k.dt = dt;
    const PointState before = st;
    update_stress(m, k, {}, st);
    const Matrix3d s_trial = deviator(before.stress.matrix()) + 2.0 * 46e9 * d;
    const double trial = std::sqrt(1.5 * (s_trial.array() * s_trial.array()).sum());
    const double d_eqps = st.eqps - before.eqps;
    ASSERT_GT(d_eqps, 0.0) << n;
    const double vm = von_mises_of(st.stress.matrix());
    EXPECT_NEAR(vm, st.flow_stress, 1e-12 * vm);
    EXPECT_NEAR(st.flow_stress, flow_stress(m, st.eqps, st.eqps_rate, before.temperature, 8930.0),
                1e-12 * vm);
    EXPECT_NEAR(vm, trial - 3.0 * 46e9 * d_eqps, 1e-10 * trial);
  }
}

// Uniaxial strain (compression) with linear hardening and a linear EOS, by the closed form for
// small strain and monotone proportional loading, eps = sum of increments:
//   elastic: s11 = (4/3) G eps; plastic: eqps = (2 G |eps| - Y)/(3 G + H), sigma_vm = Y + H eqps,
//   s11 = sign(eps) (2/3) sigma_vm, s22 = s33 = -s11/2; p = K (1/J - 1).
// Radial return with linear hardening is exact for this path, so every step must match.
TEST(MaterialsStressUpdate, LinearHardeningUniaxialStrainMatchesClosedForm) {
  const Material m = testing::linear_hardening();
  const double G = 46e9, K = 129e9, Y = 400e6, H = 100e6;
  PointState st = initial_state(m, 298.0);
  const double de = -1e-4;
  double eps = 0.0;
  for (int n = 1; n <= 200; ++n) {
    StepKinematics k;
    k.strain_increment(0, 0) = de;
    k.dt = 1e-8;
    k.J_new = st.J * std::exp(de);
    update_stress(m, k, {}, st);
    eps += de;
    const double eqps = std::max(0.0, (2.0 * G * std::abs(eps) - Y) / (3.0 * G + H));
    const double vm = eqps > 0.0 ? Y + H * eqps : 2.0 * G * std::abs(eps);
    const double s11 = -2.0 / 3.0 * vm;
    const double p = K * (1.0 / k.J_new - 1.0);
    // Roundoff, plus the cancellation in 1/J - 1 (a few ulp of 1/J, times K).
    const double tolerance = 1e-12 * (std::abs(s11) + std::abs(p)) + 4e-16 * K;
    ASSERT_NEAR(st.eqps, eqps, 1e-12) << n;
    ASSERT_NEAR(st.stress(0, 0), s11 - p, tolerance) << n;
    ASSERT_NEAR(st.stress(1, 1), -0.5 * s11 - p, tolerance) << n;
    ASSERT_NEAR(st.stress(2, 2), -0.5 * s11 - p, tolerance) << n;
  }
  EXPECT_GT(st.eqps, 0.01);  // well into the plastic range (yield at |eps| = 0.43 %)
}

// Plastic flow is isochoric: in uniaxial strain with a superposed shear the deviator stays
// traceless, J is exactly the imposed one, and the pressure (linear EOS) is the same as for a
// purely elastic material driven the same way: the plastic increment, along the traceless trial
// deviator, has no volume part.
TEST(MaterialsStressUpdate, PlasticFlowIsIncompressible) {
  const Material plastic = testing::linear_hardening();
  Material elastic = plastic;
  elastic.strength = strength::Elastic{};
  PointState a = initial_state(plastic, 298.0), b = initial_state(elastic, 298.0);
  for (int n = 1; n <= 300; ++n) {
    StepKinematics k;
    k.strain_increment(0, 0) = -1e-4;
    k.strain_increment(1, 2) = k.strain_increment(2, 1) = 3e-5;
    k.dt = 1e-8;
    k.J_new = a.J * std::exp(-1e-4);
    update_stress(plastic, k, {}, a);
    update_stress(elastic, k, {}, b);
    ASSERT_EQ(a.J, k.J_new);
    const double scale = a.stress.matrix().norm();
    ASSERT_NEAR((a.stress.matrix() + a.pressure * kI).trace(), 0.0, 1e-13 * scale) << n;
    ASSERT_NEAR(a.pressure, b.pressure, 1e-13 * std::abs(b.pressure)) << n;
    ASSERT_NEAR(a.pressure, 129e9 * (1.0 / k.J_new - 1.0), 4e-16 * 129e9 / k.J_new) << n;
  }
  EXPECT_GT(a.eqps, 0.005);
  EXPECT_LT(von_mises_of(a.stress.matrix()), von_mises_of(b.stress.matrix()));
}

// Adiabatic heating (eq 3.44): over a simple-shear path (isochoric, rho = rho0) the temperature
// rise is the sum of chi sigma_y d_eqps/(rho cp) of the steps, each with the step's flow stress.
TEST(MaterialsStressUpdate, HeatingEqualsPlasticWorkFraction) {
  const Material m = testing::cu_jc();
  PointState st = initial_state(m, 298.0);
  double rise = 0.0;
  Matrix3d L = Matrix3d::Zero();
  L(0, 1) = 1e4;
  const double dt = 1e-7;
  for (int n = 0; n < 500; ++n) {
    StepKinematics k;
    k.set_velocity_gradient(L, dt);
    k.J_new = 1.0;
    const PointState before = st;
    update_stress(m, k, {}, st);
    rise += 0.9 * st.flow_stress * (st.eqps - before.eqps) / (8930.0 * 383.0);
  }
  EXPECT_GT(rise, 10.0);  // copper sheared to gamma = 0.5: tens of kelvin
  EXPECT_NEAR(st.temperature - 298.0, rise, 1e-12 * rise);
}

// With linear hardening the heating sum is a right Riemann sum of int (Y + H e) de: it exceeds
// the closed form chi (Y eqps + H eqps^2/2)/(rho cp) by chi H sum(d_eqps^2)/(2 rho cp), which is
// between 0 and chi H eqps max(d_eqps)/(2 rho cp).
TEST(MaterialsStressUpdate, HeatingMatchesPlasticWorkIntegralForLinearHardening) {
  const Material m = testing::linear_hardening();
  PointState st = initial_state(m, 298.0);
  double max_step = 0.0;
  for (int n = 0; n < 400; ++n) {
    StepKinematics k;
    k.strain_increment(0, 1) = k.strain_increment(1, 0) = 5e-4;
    k.dt = 1e-8;
    const double before = st.eqps;
    update_stress(m, k, {}, st);
    max_step = std::max(max_step, st.eqps - before);
  }
  const double e = st.eqps, c = 0.9 / (8930.0 * 383.0);
  const double closed = c * (400e6 * e + 0.5 * 100e6 * e * e);
  const double excess = st.temperature - 298.0 - closed;
  EXPECT_GE(excess, -1e-12 * closed);
  EXPECT_LE(excess, c * 100e6 * e * max_step / 2.0 + 1e-12 * closed);
  EXPECT_GT(e, 0.2);
}

// The isothermal option leaves the temperature alone through the same plastic path, with the
// same plastic strain (this material's strength is temperature independent).
TEST(MaterialsStressUpdate, IsothermalOptionSkipsHeating) {
  const Material m = testing::linear_hardening();
  PointState hot = initial_state(m, 298.0), cold = initial_state(m, 298.0);
  for (int n = 0; n < 100; ++n) {
    StepKinematics k;
    k.strain_increment(0, 1) = k.strain_increment(1, 0) = 5e-4;
    k.dt = 1e-8;
    update_stress(m, k, {}, hot);
    update_stress(m, k, {.isothermal = true}, cold);
  }
  EXPECT_GT(cold.eqps, 0.03);
  EXPECT_EQ(cold.temperature, 298.0);
  EXPECT_GT(hot.temperature, 299.0);
  EXPECT_NEAR(cold.eqps, hot.eqps, 1e-15);
}

// Pure shear, one small elastic step gamma = 1e-4: tau = G gamma with G = MTS(298 K). The
// deviatoric work G gamma^2/2 goes into E, and the Gruneisen term turns it into a (tiny)
// pressure Gamma0 E: both by hand.
TEST(MaterialsStressUpdate, ElasticShearGivesGGamma) {
  const Material m = testing::al_ptw();
  PointState st = initial_state(m, 298.0);
  const double gamma = 1e-4;
  StepKinematics k;
  k.strain_increment(0, 1) = k.strain_increment(1, 0) = gamma / 2.0;
  k.dt = 1e-6;
  update_stress(m, k, {}, st);
  const double G = mts_al(298.0);
  EXPECT_EQ(st.eqps, 0.0);
  EXPECT_NEAR(st.stress(0, 1), G * gamma, 1e-14 * G * gamma);
  EXPECT_NEAR(st.stress(1, 0), G * gamma, 1e-14 * G * gamma);
  EXPECT_NEAR(st.energy, 0.5 * G * gamma * gamma, 1e-14 * G * gamma * gamma);
  EXPECT_NEAR(st.pressure, 1.97 * 0.5 * G * gamma * gamma, 1e-12 * G * gamma * gamma);
  EXPECT_NEAR(st.stress(0, 0), -st.pressure, 1e-9);
  EXPECT_EQ(st.shear_modulus, G);
}

// Simple shear with spin (the material-test's simple-shear mode) to gamma = 1e-3 in 100 steps:
// tau = G gamma up to the O(gamma^2) of the Jaumann rate.
TEST(MaterialsStressUpdate, ElasticSimpleShearWithSpin) {
  const Material m = testing::al_elastic();
  PointState st = initial_state(m, 298.0);
  Matrix3d L = Matrix3d::Zero();
  L(0, 1) = 1e3;
  const double dt = 1e-8;
  for (int n = 0; n < 100; ++n) {
    StepKinematics k;
    k.set_velocity_gradient(L, dt);
    update_stress(m, k, {}, st);
  }
  const double gamma = 1e-3, G = 26e9;
  EXPECT_NEAR(st.stress(0, 1), G * gamma, G * gamma * gamma);
  EXPECT_NEAR(st.stress(0, 0), -st.stress(1, 1) - 2.0 * st.pressure, 1e-6 * G * gamma);
}

// A fresh point: stress-free, J = 1, diagnostics from the models at T and rho0.
TEST(MaterialsStressUpdate, InitialStateFillsDiagnostics) {
  const Material m = testing::al_ptw();
  const PointState st = initial_state(m, 298.0);
  EXPECT_EQ(st.stress.matrix(), Matrix3d::Zero());
  EXPECT_EQ(st.J, 1.0);
  EXPECT_EQ(st.eqps, 0.0);
  EXPECT_EQ(st.temperature, 298.0);
  EXPECT_EQ(st.pressure, 0.0);
  EXPECT_NEAR(st.shear_modulus, mts_al(298.0), 1e-15 * st.shear_modulus);
  EXPECT_DOUBLE_EQ(st.melt_temperature, 1220.0);
  // At the rate floor the erf of eq 2.7 is 1 and tau_y = y_inf: sigma_y = 2 y_inf mu.
  EXPECT_NEAR(st.flow_stress, 2.0 * 0.002003 * mts_al(298.0), 1e-13 * st.flow_stress);
  EXPECT_TRUE(std::isinf(initial_state(testing::al_elastic(), 298.0).flow_stress));
}

}  // namespace
}  // namespace coldspray::materials
