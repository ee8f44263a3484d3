#include "pd/stepper.hpp"

#include <omp.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "bodies/material_state.hpp"
#include "bodies/update_points.hpp"
#include "materials/artificial_viscosity.hpp"
#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/forces.hpp"
#include "pd/grip.hpp"
#include "pd/pair_forces.hpp"
#include "pd/symmetry.hpp"
#include "pd/tensor_field.hpp"
#include "pd/time_step.hpp"

namespace coldspray::pd {

namespace {

// v += dt/2 a at every point. A held component stays at zero; the kinetic energy a hold takes
// (once, when a moving face is first held) goes to the budget's contact entry, as the MPM books
// the velocity corrections of its contact and held nodes. A gripped point moves at the grip's
// velocity (pd/grip.hpp); the kinetic energy its ramp gives goes to the same entry.
void kick(State& s, double t) {
  bodies::Points& P = s.points;
  const double half = 0.5 * s.dt;
  const Eigen::Vector3d grip = grip_velocity_at(s, t);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      if (s.gripped[i]) {
        // The grip's work in speeding its points up along its ramp.
        P.contact_work[i] +=
            0.5 * P.mass[i] * (grip[d] * grip[d] - P.velocity[d][i] * P.velocity[d][i]);
        P.velocity[d][i] = grip[d];
      } else if (s.held[i] >> d & 1) {
        P.contact_work[i] -= 0.5 * P.mass[i] * P.velocity[d][i] * P.velocity[d][i];
        P.velocity[d][i] = 0.0;
      } else {
        P.velocity[d][i] += half * s.acceleration[d][i];
      }
    }
}

// x += dt v.
void drift(State& s) {
  bodies::Points& P = s.points;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      P.displacement[d][i] = s.dt * P.velocity[d][i];
      P.position[d][i] += P.displacement[d][i];
    }
}

// Eqs 5, 28-31 at every point: F and L = Fdot F^-1 from the family, then the materials' update
// (the MPM's, bodies/update_points.hpp), A = P K^-1 with P = J (sigma - q I) F^-T and, for the
// control along the flow, the point's flow direction and softening (pd/control_along_flow.hpp).
// Returns the largest (c + |v|) / min(1, lambda / 0.7), lambda the point's compressed stretch
// (pd/time_step.hpp): the speed at which a signal crosses the reference lattice, over the
// factor by which compression lowers the stable step.
double update_stress(State& s) {
  bodies::Points& P = s.points;
  const double dt = s.dt;
  const bool along_flow = s.settings.control_stiffness == case_file::ControlStiffness::Flow;
  double max_speed = 0.0;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const bodies::BodyRange& body = s.bodies[b];
    const BondWeights weights = bond_weights(s, b);
    materials::visit_models(body.material, [&](const auto& models) {
      auto kinematics_of = [&](std::size_t i) {
        const Deformation def = deformation(s.families, s.neighbours, weights,
                                            tensor_at(s.shape_inverse, i), s.moment_inverse[i], i);
        store_tensor(def.F, s.deformation_gradient, i);
        s.compressed_stretch[i] = compressed_stretch(def.F);
        s.velocity_fit[i] = def.velocity_fit;
        materials::StepKinematics k;
        k.set_velocity_gradient(def.Fdot * def.F.inverse(), dt);  // eqs 28-29
        k.J_new = def.F.determinant();
        return k;
      };
      auto complete_point = [&](std::size_t i, const materials::StepKinematics& k,
                                const materials::PointState& state) {
        const double eqps_before = P.eqps[i];
        const bool flowed = state.eqps > eqps_before;
        bodies::store_point_state(state, P, i);
        if (state.eqps > eqps_before)
          P.plastic_work[i] +=
              state.flow_stress * (state.eqps - eqps_before) * P.volume0[i] * state.J;
        const double trace_D = k.strain_increment.trace() / dt;
        const double q = materials::bulk_viscous_pressure(
            s.viscosity, body.material.density / state.J, body.spacing, P.sound_speed[i], trace_D);
        P.bulk_viscosity[i] = q;
        P.viscous_work[i] -= q * trace_D * dt * P.volume0[i] * state.J;
        const Eigen::Matrix3d F = tensor_at(s.deformation_gradient, i);
        Eigen::Matrix3d sigma = bodies::stress_at(P, i).matrix();
        if (along_flow) {
          s.flow_softening[i] =
              flow_softening(models, state, flowed, body.material.density / state.J);
          store_tensor(flow_direction(sigma), s.flow_direction, i);
        }
        sigma.diagonal().array() -= q;
        const Eigen::Matrix3d A =
            state.J * sigma * F.inverse().transpose() * tensor_at(s.shape_inverse, i);
        store_tensor(A, s.piola_over_shape, i);
        if (!(state.J > 0.0))
          bodies::record_fault(s.fault, i, "inverted deformation gradient (det F <= 0)");
        else if (!A.allFinite() || !std::isfinite(state.temperature))
          bodies::record_fault(s.fault, i, "non-finite stress or temperature");
        else if (s.compressed_stretch[i] < kCrushedStretch)
          bodies::record_fault(s.fault, i,
                               "crushed: the smallest principal stretch of F is below 0.01, and "
                               "the time step, which follows it, would stall the run");
      };
      const std::size_t batches = bodies::batch_count(body);
#pragma omp parallel for schedule(static)
      for (std::size_t batch = 0; batch < batches; ++batch)
        bodies::update_batches(models, P, body, batch, batch + 1, kinematics_of, complete_point);
    });
#pragma omp parallel for schedule(static) reduction(max : max_speed)
    for (std::size_t i = body.begin; i < body.end; ++i) {
      const double speed =
          std::sqrt(P.velocity[0][i] * P.velocity[0][i] + P.velocity[1][i] * P.velocity[1][i] +
                    P.velocity[2][i] * P.velocity[2][i]);
      max_speed = std::max(
          max_speed, (P.sound_speed[i] + speed) / step_length_factor(s.compressed_stretch[i]));
    }
  }
  return max_speed;
}

// a = f / rho0 at every point (the bonds' and the control's rate from the pairs,
// pd/pair_forces.hpp, the control's force advanced by its rate over the step that moved the
// points, and the contacts'), with the absorbing faces' dashpots (thesis eqs 3.45-3.46), held
// points at rest and gripped points unaccelerated: the grip's force cancels the others.
void accelerate(State& s) {
  bodies::Points& P = s.points;
  pair_forces(s);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < P.size(); ++i) {
    const ForceDensity f{s.pair_bonds[i].head<3>(), s.pair_control[i].head<3>(),
                         contact_density(s, i)};
    Eigen::Vector3d total = f.bonds + f.contact;
    for (int d = 0; d < 3; ++d) {
      s.control_force[d][i] += s.dt * f.control_rate[d];
      s.contact_force[d][i] = f.contact[d];
      total[d] += s.control_force[d][i];
    }
    // The points another body pushes on: the contact area of the impact metrics.
    P.touching[i] = f.contact.squaredNorm() > 0.0;
    P.touched[i] |= P.touching[i];
    // The points an adhesive contact holds: the bonded area of the verdict (metrics/verdict.hpp).
    if (s.bonding) P.bonded_to[i] = adhesive_partner(s, i);
    const double rho0 = s.bodies[P.body[i]].material.density;
    for (int d = 0; d < 3; ++d) s.acceleration[d][i] = (s.held[i] >> d & 1) ? 0.0 : total[d] / rho0;
    if (s.gripped[i])
      for (int d = 0; d < 3; ++d) {
        s.external_force[d][i] = -total[d] * P.volume0[i];
        s.acceleration[d][i] = 0.0;
      }
  }
  for (bodies::AbsorbingPoint& a : s.absorbing)
    for (int d = 0; d < 3; ++d) {
      s.external_force[d][a.point] = -a.damping[d] * P.velocity[d][a.point];
      if (!(s.held[a.point] >> d & 1))
        s.acceleration[d][a.point] += s.external_force[d][a.point] / P.mass[a.point];
    }
}

// The works of the step's control, contact and dashpot forces f^{n+1}, booked as f^{n+1} .
// v^{n+1} dt: in velocity Verlet f^{n+1} acts over (x^{n+2} - x^n) / 2 = v^{n+1} dt, so that a
// conservative force's work telescopes. (With v^{n+1/2}, the work is off by dt^2/2 |f|^2 / rho
// each step, always of one sign.)
void book_works(State& s) {
  bodies::Points& P = s.points;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < P.size(); ++i) {
    double control = 0.0, contact = 0.0;
    for (int d = 0; d < 3; ++d) {
      control += s.control_force[d][i] * P.velocity[d][i];
      contact += s.contact_force[d][i] * P.velocity[d][i];
    }
    P.viscous_work[i] -= control * P.volume0[i] * s.dt;
    P.contact_work[i] += contact * P.volume0[i] * s.dt;
    // The grip's work, which the budget books with the holds' (pd/grip.hpp).
    if (s.gripped[i])
      for (int d = 0; d < 3; ++d)
        P.contact_work[i] += s.external_force[d][i] * P.velocity[d][i] * s.dt;
  }
  for (bodies::AbsorbingPoint& a : s.absorbing)
    for (int d = 0; d < 3; ++d)
      a.absorbed -= s.external_force[d][a.point] * P.velocity[d][a.point] * s.dt;
}

// Contact model 2 (pd/interface_bonds.hpp): each candidate pair's bond forms, remembers its
// largest stretch or breaks, at the step's new positions, before the forces read it.
void update_interface_bonds(State& s) {
  if (!s.contact.remembers_stretch) return;
  const Neighbours& N = s.neighbours;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < N.real; ++i)
    for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c) {
      const std::size_t j = s.contact.other[c];
      const ContactLaw& law = contact_law_between(s, i, j);
      if (law.kind != ContactLaw::Kind::InterfaceBonds) continue;
      const double r = (N.position[i] - N.position[j]).head<3>().norm();
      double& largest = s.contact.largest_stretch[c];
      largest =
          next_largest_stretch(law.interface, r / contact_distance(law, N, i, j) - 1.0, largest);
    }
}

// The impulse between each pair of bodies over the step (contact.csv), summed over the contact
// pairs in point order.
void sum_contact_impulses(State& s) {
  const std::size_t m = s.bodies.size();
  for (auto& impulse : s.contact_impulse) impulse = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < s.points.size(); ++i)
    for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c) {
      const std::size_t j = s.contact.other[c];
      const Eigen::Vector3d f = contact_force(s, i, c) * (s.points.volume0[i] * s.dt);
      auto& impulse = s.contact_impulse[s.points.body[i] * m + s.neighbours.body[j]];
      for (int d = 0; d < 3; ++d) impulse[d] += f[d];
    }
}

}  // namespace

double stable_time_step(const State& s, double cfl) {
  return cfl * s.min_spacing / s.max_signal_speed;
}

void step(State& s) {
  kick(s, s.time + 0.5 * s.dt);  // v^{n+1/2}
  drift(s);                      // x^{n+1}
  refresh_neighbours(s);
  if (s.contact.stale(s.neighbours)) {
    double reach = 0.0;
    for (const ContactLaw& law : s.contact_law) reach = std::max(reach, law.reach);
    s.contact.build(s.neighbours, reach + s.contact.skin);
  }
  update_interface_bonds(s);
  s.max_signal_speed = update_stress(s);
  bodies::raise_recorded_fault(s);
  refresh_ghost_tensors(s);
  accelerate(s);           // a^{n+1}
  kick(s, s.time + s.dt);  // v^{n+1}
  book_works(s);
  sum_contact_impulses(s);
  s.time += s.dt;
  ++s.step;
}

}  // namespace coldspray::pd
