// Steps 9-11 of the MUSL step (thesis eqs 3.34-3.36, Appendix A): velocity gradient, density,
// artificial viscosity, the material's stress update, then the position update and the checks
// for faults. Declared in phases.hpp; instantiated here for each shape function and geometry.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "bodies/material_state.hpp"
#include "bodies/update_points.hpp"
#include "bonding/bond_law.hpp"
#include "core/double4.hpp"
#include "materials/artificial_viscosity.hpp"
#include "materials/model_dispatch.hpp"
#include "mpm/departures.hpp"
#include "mpm/phases.hpp"

namespace coldspray::mpm {

namespace {

// After point p's position update: a point that moved out of the domain leaves the run at the
// end of the step (mpm/departures.hpp); a non-finite state or, in r-z, a crossing of the axis
// is a fault.
void check_point(State& s, std::size_t p) {
  const Points& P = s.points;
  const char* cause = nullptr;
  bool finite = true;
  for (int d = 0; d < 3; ++d)
    finite = finite && std::isfinite(P.position[d][p]) && std::isfinite(P.velocity[d][p]);
  for (int c = 0; c < 6; ++c) finite = finite && std::isfinite(P.stress[c][p]);
  if (!finite) cause = "non-finite position, velocity or stress";
  // (Before the domain test, whose lower r bound is the axis.)
  if (s.layout.axisymmetric && cause == nullptr && P.position[0][p] <= 0.0)
    cause = "crossed the axis r = 0";
  if (cause == nullptr) {
    if (outside_domain(s.layout, P, p)) {
#pragma omp atomic
      ++s.departing;
    }
    return;
  }
  bodies::record_fault(s.fault, p, cause);
}

// Steps 9-11 for batches [first, end) of one body (eqs 3.34-3.36, Appendix A), through the
// solvers' shared batch update (bodies/update_points.hpp). Returns the largest c + |v| of the
// points.
template <class Shape, bool Axisymmetric>
double update_body_stress(State& s, const BodyRange& body, std::size_t first_batch,
                          std::size_t end_batch) {
  Points& P = s.points;
  const double dt = s.dt;
  const int b = static_cast<int>(&body - s.bodies.data());

  // Eqs 3.34-3.36 and the artificial viscosity for point p: the step's kinematics.
  auto kinematics_of = [&](std::size_t p) {
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    // L = sum_I v_I (x) grad N_I, with v_I = p_I / m_I of the point's body, by columns:
    // L(:, j) = sum_I v_I dN_I/dx_j, a column to a four-double vector (the last lane unused), so
    // a node costs three vector multiply-adds and the sums stay in registers. (As a 3x3 array
    // of scalars, they went through the stack, and one load reading them back had 9 % of
    // this function's samples.)
    Double4 L0 = {0.0, 0.0, 0.0, 0.0}, L1 = L0, L2 = L0, v_N = L0;
    for_each_node_view(
        s, st, near_contact(s, st), b,
        [&](std::size_t, double w, double gx, double gy, double gz, const NodeView& v) {
          const Double4 v_I = {v.v[0], v.v[1], v.v[2], 0.0};
          L0 += v_I * gx;
          L1 += v_I * gy;
          L2 += v_I * gz;
          if constexpr (Axisymmetric) v_N += v_I * w;
        });
    // L(i, j) = Lj[i]. In r-z the hoop strain rate is v_r / r.
    const double L11 = Axisymmetric ? v_N[0] / P.position[0][p] : L1[1];

    // D dt and W dt (eq 3.34): the symmetric and skew parts of L dt.
    materials::StepKinematics k;
    k.strain_increment = {{L0[0] * dt, L11 * dt, L2[2] * dt, 0.5 * (L1[0] + L0[1]) * dt,
                           0.5 * (L2[1] + L1[2]) * dt, 0.5 * (L2[0] + L0[2]) * dt}};
    k.spin_increment = {
        {0.5 * (L1[0] - L0[1]) * dt, 0.5 * (L2[1] - L1[2]) * dt, 0.5 * (L2[0] - L0[2]) * dt}};
    k.dt = dt;
    k.J_new = P.J[p] * (1.0 + k.strain_increment.trace());  // eq 3.36

    // Artificial bulk viscosity on the step's volumetric rate, and its work.
    const double trace_L = L0[0] + L11 + L2[2];
    const double rho_new = body.material.density / k.J_new;
    const double q = materials::bulk_viscous_pressure(s.viscosity, rho_new, s.layout.h,
                                                      P.sound_speed[p], trace_L);
    P.bulk_viscosity[p] = q;
    P.viscous_work[p] -= q * trace_L * dt * P.volume0[p] * k.J_new;
    return k;
  };

  double max_speed = 0.0;
  materials::visit_models(body.material, [&](const auto& models) {
    // After the material update: the point's work, bonding and position.
    auto complete_point = [&](std::size_t p, const materials::StepKinematics& k,
                              const materials::PointState& state) {
      const double eqps_before = P.eqps[p];
      store_point_state(state, P, p);
      if (state.eqps > eqps_before)
        P.plastic_work[p] +=
            state.flow_stress * (state.eqps - eqps_before) * P.volume0[p] * state.J;
      // Eqs 4.5 / 4.16a: D_bond grows at surface points in contact (the set S); the run's own,
      // or that of each bond law it shadows.
      if (P.touching[p]) {
        P.touched[p] = 1;
        const Eigen::Vector3d n(P.contact_normal[0][p], P.contact_normal[1][p],
                                P.contact_normal[2][p]);
        const double d_eqps = state.eqps - eqps_before;
        if (s.bond_shadows.active())
          s.bond_shadows.grow(p, state.stress.matrix(), d_eqps, n, dt);
        else
          P.bond[p] += bonding::bond_increment(s.bond_law, state.stress.matrix(), d_eqps, n, dt);
      }
      for (int d = 0; d < 3; ++d) {
        P.position[d][p] += P.displacement[d][p];
        P.half_width[d][p] *= 1.0 + k.strain_increment(d, d);
      }
      check_point(s, p);
    };

    max_speed = bodies::update_batches(models, P, body, first_batch, end_batch, kinematics_of,
                                       complete_point);
  });
  return max_speed;
}

}  // namespace

template <class Shape, bool Axisymmetric>
double update_stress_share(State& s, std::size_t first, std::size_t end) {
  double max_speed = 0.0;
  std::size_t offset = 0;  // the body's first batch in the step's sequence
  for (const BodyRange& body : s.bodies) {
    const std::size_t batches = bodies::batch_count(body);
    const std::size_t lo = std::max(first, offset), hi = std::min(end, offset + batches);
    if (lo < hi)
      max_speed = std::max(
          max_speed, update_body_stress<Shape, Axisymmetric>(s, body, lo - offset, hi - offset));
    offset += batches;
  }
  return max_speed;
}

std::size_t stress_batch_count(const State& s) {
  std::size_t batches = 0;
  for (const BodyRange& body : s.bodies) batches += bodies::batch_count(body);
  return batches;
}

template double update_stress_share<LinearShape, false>(State&, std::size_t, std::size_t);
template double update_stress_share<LinearShape, true>(State&, std::size_t, std::size_t);
template double update_stress_share<GimpShape, false>(State&, std::size_t, std::size_t);
template double update_stress_share<GimpShape, true>(State&, std::size_t, std::size_t);

}  // namespace coldspray::mpm
