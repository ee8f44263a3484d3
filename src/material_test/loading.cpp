#include "material_test/loading.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <ostream>

#include "core/error.hpp"
#include "materials/stress_update.hpp"
#include "materials/symmetric_tensor.hpp"

namespace coldspray::material_test {

using Eigen::Matrix3d;
using materials::PointState;

Mode parse_mode(std::string_view name) {
  if (name == "uniaxial-strain") return Mode::UniaxialStrain;
  if (name == "uniaxial-stress") return Mode::UniaxialStress;
  if (name == "simple-shear") return Mode::SimpleShear;
  throw InputError("--mode", "",
                   fmt::format("unknown mode '{}' (expected uniaxial-strain, "
                               "uniaxial-stress or simple-shear)",
                               name));
}

namespace {

void check(const Loading& l) {
  if (!(l.strain_rate > 0.0) || !std::isfinite(l.strain_rate))
    throw InputError("--strain-rate", "", "must be a positive rate");
  if (l.final_strain == 0.0 || !std::isfinite(l.final_strain))
    throw InputError("--final-strain", "", "must be non-zero (negative is compression)");
  if (!(l.temperature > 0.0)) throw InputError("--temperature", "", "must be above 0 K");
  if (l.steps < 1 || l.steps > kMaxSteps)
    throw InputError("--steps", "", fmt::format("must be from 1 to {}", kMaxSteps));
}

// One step with velocity gradient L held constant over dt: strain increment sym(L) dt, spin
// increment skew(L) dt, and J advanced exactly for constant tr(L).
PointState advance(const materials::Material& m, const materials::UpdateOptions& opt,
                   const PointState& start, const Matrix3d& L, double dt) {
  materials::StepKinematics k;
  k.set_velocity_gradient(L, dt);
  k.J_new = start.J * std::exp(L.trace() * dt);
  PointState next = start;
  materials::update_stress(m, k, opt, next);
  return next;
}

// Uniaxial stress: find the lateral rate a for which sigma_yy (= sigma_zz by symmetry) vanishes
// at the end of the step. sigma_yy grows monotonically with a, so a secant iteration from the
// previous step's rate converges in a few updates.
PointState advance_uniaxial_stress(const materials::Material& m,
                                   const materials::UpdateOptions& opt, const PointState& start,
                                   double r, double dt, double& lateral_rate) {
  auto lateral_stress = [&](double a, PointState& out) {
    Matrix3d L = Matrix3d::Zero();
    L(0, 0) = r;
    L(1, 1) = L(2, 2) = a;
    out = advance(m, opt, start, L, dt);
    return out.stress(1, 1);
  };
  // Stresses are resolved only to about K ulp(J): the tolerance allows for that floor.
  const double resolution = 64.0 * std::numeric_limits<double>::epsilon() *
                            (m.elastic.bulk_modulus + 4.0 / 3.0 * m.elastic.shear_modulus);
  PointState s0, s1;
  double a0 = lateral_rate;
  double a1 = lateral_rate + 1e-3 * std::abs(r);
  double f0 = lateral_stress(a0, s0);
  double f1 = lateral_stress(a1, s1);
  constexpr int kMaxIterations = 60;
  for (int it = 0; it < kMaxIterations; ++it) {
    const double tolerance = 1e-10 * std::abs(s1.stress(0, 0)) + resolution;
    if (std::abs(f1) <= tolerance) {
      lateral_rate = a1;
      return s1;
    }
    if (f1 == f0) break;
    const double a2 = a1 - f1 * (a1 - a0) / (f1 - f0);
    a0 = a1;
    f0 = f1;
    a1 = a2;
    f1 = lateral_stress(a1, s1);
  }
  throw RunFault("uniaxial-stress: the lateral stress iteration did not converge");
}

Sample sample(const materials::Material& m, const PointState& s, double time, double strain) {
  return Sample{time,
                strain,
                s.eqps,
                s.eqps_rate,
                s.temperature,
                s.melt_temperature,
                s.shear_modulus,
                s.flow_stress,
                materials::von_mises_stress(s.stress),
                s.pressure,
                m.density / s.J};
}

}  // namespace

void drive(const materials::Material& material, const Loading& loading,
           const std::function<void(const Sample&)>& record) {
  check(loading);
  const double r = std::copysign(loading.strain_rate, loading.final_strain);
  const double dt = std::abs(loading.final_strain) / loading.strain_rate / loading.steps;
  const materials::UpdateOptions opt{.isothermal = loading.isothermal};

  Matrix3d L = Matrix3d::Zero();
  if (loading.mode == Mode::SimpleShear)
    L(0, 1) = r;
  else
    L(0, 0) = r;

  PointState state = materials::initial_state(material, loading.temperature);
  // Elastic guess for the lateral rate: -nu r, nu from G and K.
  const double G = material.elastic.shear_modulus, K = material.elastic.bulk_modulus;
  double lateral_rate = -(3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G)) * r;

  record(sample(material, state, 0.0, 0.0));
  for (int n = 1; n <= loading.steps; ++n) {
    state = loading.mode == Mode::UniaxialStress
                ? advance_uniaxial_stress(material, opt, state, r, dt, lateral_rate)
                : advance(material, opt, state, L, dt);
    const Sample row = sample(material, state, n * dt, n * dt * r);
    if (!std::isfinite(row.von_mises) || !std::isfinite(row.pressure) ||
        !std::isfinite(row.temperature))
      throw RunFault(fmt::format("non-finite stress or temperature at step {} (strain {:.6g})", n,
                                 row.strain));
    record(row);
  }
}

void write_csv_header(std::ostream& out) {
  out << "time,strain,eqps,eqps_rate,temperature,melt_temperature,shear_modulus,flow_stress,"
         "von_mises,pressure,density\n";
}

void write_csv_row(std::ostream& out, const Sample& s) {
  out << fmt::format(
      "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},"
      "{:.10g},{:.10g}\n",
      s.time, s.strain, s.eqps, s.eqps_rate, s.temperature, s.melt_temperature, s.shear_modulus,
      s.flow_stress, s.von_mises, s.pressure, s.density);
}

}  // namespace coldspray::material_test
