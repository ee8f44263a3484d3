#include "pd/stepper.hpp"

#include <omp.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <variant>

#include "bodies/grip.hpp"
#include "bodies/material_state.hpp"
#include "bodies/update_points.hpp"
#include "materials/artificial_viscosity.hpp"
#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/forces.hpp"
#include "pd/pair_forces.hpp"
#include "pd/symmetry.hpp"
#include "pd/tensor_field.hpp"
#include "pd/time_step.hpp"

namespace coldspray::pd {

namespace {

// v += dt/2 a at every point. A held component stays at zero; the kinetic energy a hold takes
// (once, when a moving face is first held) goes to the budget's contact entry, as the MPM books
// the velocity corrections of its contact and held nodes. A gripped point moves at the grip's
// velocity (bodies/grip.hpp); the kinetic energy its ramp gives goes to the same entry.
//
// With `contact_kick` (subcycling), the contact's part of a is replaced by the contact impulse
// density that array holds, N s/m^3, and its work booked as the kinetic energy it gives: the
// impulse times the mean of the velocities before and after the kick.
void kick(State& s, double t, const std::array<std::vector<double>, 3>* contact_kick = nullptr) {
  bodies::Points& P = s.points;
  const double half = 0.5 * s.dt;
  const Eigen::Vector3d grip = bodies::grip_velocity_at(s, t);
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!s.advancing[P.body[i]]) continue;
    for (int d = 0; d < 3; ++d) {
      if (s.gripped[i]) {
        // The grip's work in speeding its points up along its ramp.
        P.contact_work[i] +=
            0.5 * P.mass[i] * (grip[d] * grip[d] - P.velocity[d][i] * P.velocity[d][i]);
        P.velocity[d][i] = grip[d];
      } else if (s.held[i] >> d & 1) {
        P.contact_work[i] -= 0.5 * P.mass[i] * P.velocity[d][i] * P.velocity[d][i];
        P.velocity[d][i] = 0.0;
      } else if (contact_kick) {
        const double rho0 = s.bodies[P.body[i]].material.density;
        const double before = P.velocity[d][i];
        P.velocity[d][i] += half * (s.acceleration[d][i] - s.contact_force[d][i] / rho0) +
                            (*contact_kick)[d][i] / rho0;
        P.contact_work[i] +=
            (*contact_kick)[d][i] * P.volume0[i] * 0.5 * (before + P.velocity[d][i]);
      } else {
        P.velocity[d][i] += half * s.acceleration[d][i];
      }
    }
  }
}

// x += dt v, at every point: a body that takes one step while others take several moves at its
// v^{n+1/2} through their substeps, as its own step would move it.
void drift(State& s) {
  bodies::Points& P = s.points;
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      P.displacement[d][i] = s.dt * P.velocity[d][i];
      P.position[d][i] += P.displacement[d][i];
    }
}

// Eqs 5, 28-31 at every point of the bodies the step advances: F and L = Fdot F^-1 from the family,
// then the materials' update (the MPM's, bodies/update_points.hpp), A = P K^-1 with P = J (sigma -
// q I) F^-T and, for the control along the flow, the point's flow direction and softening
// (pd/control_along_flow.hpp). Returns the largest (c + |v|) / min(1, lambda / 0.7), lambda the
// point's compressed stretch (pd/time_step.hpp): the speed at which a signal crosses the reference
// lattice, over the factor by which compression lowers the stable step.
double update_stress(State& s) {
  bodies::Points& P = s.points;
  const double dt = s.dt;
  const bool along_flow = s.settings.control_stiffness == case_file::ControlStiffness::Flow;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (!s.advancing[b]) continue;
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
#pragma omp parallel for schedule(static) if (threaded(s))
      for (std::size_t batch = 0; batch < batches; ++batch)
        bodies::update_batches(models, P, body, batch, batch + 1, kinematics_of, complete_point);
    });
    double max_speed = 0.0;
#pragma omp parallel for schedule(static) if (threaded(s)) reduction(max : max_speed)
    for (std::size_t i = body.begin; i < body.end; ++i) {
      const double speed =
          std::sqrt(P.velocity[0][i] * P.velocity[0][i] + P.velocity[1][i] * P.velocity[1][i] +
                    P.velocity[2][i] * P.velocity[2][i]);
      max_speed = std::max(
          max_speed, (P.sound_speed[i] + speed) / step_length_factor(s.compressed_stretch[i]));
    }
    s.body_signal_speed[b] = max_speed;
  }
  return *std::max_element(s.body_signal_speed.begin(), s.body_signal_speed.end());
}

// a = f / rho0 at every point of the bodies the step advances (the bonds' and the control's rate
// from the pairs, pd/pair_forces.hpp, the control's force advanced by its rate over the step
// that moved the points, and the contacts'), with the absorbing faces' dashpots (thesis eqs
// 3.45-3.46), held points at rest and gripped points unaccelerated: the grip's force cancels the
// others.
void accelerate(State& s) {
  bodies::Points& P = s.points;
  pair_forces(s);
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!s.advancing[P.body[i]]) continue;
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
  for (bodies::AbsorbingPoint& a : s.absorbing) {
    if (!s.advancing[P.body[a.point]]) continue;
    for (int d = 0; d < 3; ++d) {
      s.external_force[d][a.point] = -a.damping[d] * P.velocity[d][a.point];
      if (!(s.held[a.point] >> d & 1))
        s.acceleration[d][a.point] += s.external_force[d][a.point] / P.mass[a.point];
    }
  }
}

// The works of the step's control, contact and dashpot forces f^{n+1}, booked as f^{n+1} .
// v^{n+1} dt: in velocity Verlet f^{n+1} acts over (x^{n+2} - x^n) / 2 = v^{n+1} dt, so that a
// conservative force's work telescopes. (With v^{n+1/2}, the work is off by dt^2/2 |f|^2 / rho
// each step, always of one sign.)
void book_works(State& s, bool book_contact = true) {
  bodies::Points& P = s.points;
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!s.advancing[P.body[i]]) continue;
    double control = 0.0, contact = 0.0;
    for (int d = 0; d < 3; ++d) {
      control += s.control_force[d][i] * P.velocity[d][i];
      contact += s.contact_force[d][i] * P.velocity[d][i];
    }
    P.viscous_work[i] -= control * P.volume0[i] * s.dt;
    if (book_contact) P.contact_work[i] += contact * P.volume0[i] * s.dt;
    // The grip's work, which the budget books with the holds' (bodies/grip.hpp).
    if (s.gripped[i])
      for (int d = 0; d < 3; ++d)
        P.contact_work[i] += s.external_force[d][i] * P.velocity[d][i] * s.dt;
  }
  for (bodies::AbsorbingPoint& a : s.absorbing)
    if (s.advancing[P.body[a.point]])
      for (int d = 0; d < 3; ++d)
        a.absorbed -= s.external_force[d][a.point] * P.velocity[d][a.point] * s.dt;
}

// Contact model 2 (pd/laws/interface_bonds.hpp): each candidate pair's bond forms, remembers its
// largest stretch or breaks, at the step's new positions, before the forces read it.
void update_interface_bonds(State& s) {
  if (!s.contact.remembers_stretch) return;
  const Neighbours& N = s.neighbours;
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < N.real; ++i)
    for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c) {
      const std::size_t j = s.contact.other[c];
      const auto* law = std::get_if<InterfaceBonds>(&contact_law_between(s, i, j));
      if (law == nullptr) continue;
      const double r = (N.position[i] - N.position[j]).head<3>().norm();
      double& largest = s.contact.largest_stretch[c];
      largest = next_largest_stretch(law->bond, law->stretch({N, s.contact, i, j, c}, r), largest);
    }
}

// Adds the impulse between each pair of bodies over s.dt (contact.csv), summed over the contact
// pairs in point order.
void add_contact_impulses(State& s) {
  const std::size_t m = s.bodies.size();
  for (std::size_t i = 0; i < s.points.size(); ++i)
    for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c) {
      const std::size_t j = s.contact.other[c];
      const Eigen::Vector3d f = contact_force(s, i, c) * (s.points.volume0[i] * s.dt);
      auto& impulse = s.contact_impulse[s.points.body[i] * m + s.neighbours.body[j]];
      for (int d = 0; d < 3; ++d) impulse[d] += f[d];
    }
}

// The positions' consequences at the start of a (sub)step: x^{n+1} for the neighbours and the
// contact list, and contact model 2's bonds at them.
void move(State& s) {
  drift(s);
  refresh_neighbours(s);
  if (s.contact.stale(s.neighbours)) {
    s.contact.build(s.neighbours, largest_reach(s.contact_law) + s.contact.skin);
  }
  update_interface_bonds(s);
}

// The forces at the new positions of the bodies the step advances, and v^{n+1} from them
// (`contact_kick`: as kick's).
void complete(State& s, double end,
              const std::array<std::vector<double>, 3>* contact_kick = nullptr) {
  s.max_signal_speed = update_stress(s);
  bodies::raise_recorded_fault(s);
  refresh_ghost_tensors(s);
  accelerate(s);               // a^{n+1}
  kick(s, end, contact_kick);  // v^{n+1}
  book_works(s, /*book_contact=*/contact_kick == nullptr);
}

// The body with the most points: the one whose stable step a subcycled step takes.
std::size_t largest_body(const State& s) {
  std::size_t largest = 0;
  for (std::size_t b = 1; b < s.bodies.size(); ++b)
    if (s.bodies[b].end - s.bodies[b].begin > s.bodies[largest].end - s.bodies[largest].begin)
      largest = b;
  return largest;
}

// A body's own stable step (stable_time_step's, for its points alone).
double own_step(const State& s, std::size_t b) {
  return s.cfl * s.bodies[b].spacing / s.body_signal_speed[b];
}

// Subcycling: the bodies whose own stable step is shorter than s.dt take `substeps` steps of
// s.dt / substeps (enough for the shortest of them, at most kMaxSubsteps), the others one;
// marks the first in `fast`. 1 when every body takes s.dt.
int plan_substeps(const State& s, std::vector<std::uint8_t>& fast) {
  double shortest = s.dt;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    fast[b] = own_step(s, b) < s.dt;
    if (fast[b]) shortest = std::min(shortest, own_step(s, b));
  }
  return std::min(kMaxSubsteps, static_cast<int>(std::ceil(s.dt / shortest * (1.0 - 1e-12))));
}

void set_advancing(State& s, const std::vector<std::uint8_t>& fast, bool value) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) s.advancing[b] = fast[b] == value;
}

// One step of s.dt for the slow bodies, `substeps` of the fast ones (docs/pd.md, "Subcycling"):
// velocity Verlet for each at its own step. The slow bodies move at their v^{n+1/2} through the
// substeps, so that the fast ones meet them where a single step would put them. Their contact
// force enters their kicks as the impulse the fast bodies' kicks gave in return: the contact
// force f_m at the end of each substep m acts on the fast bodies over dt/2 in each of the two
// kicks beside it, so over the step the slow bodies take dt (f_0 / 2 + f_1 + ... + f_(k-1) +
// f_k / 2), dt the substep, and momentum is conserved whatever the steps: Dt/2 f_0 in their
// first kick (Dt the step, as velocity Verlet) and the rest in their second.
void subcycled_step(State& s, std::vector<std::uint8_t>& fast, int substeps) {
  const double step = s.dt, t0 = s.time, substep = step / substeps;
  const bodies::Points& P = s.points;
  // The slow bodies' points' contact impulse density over a part of the step (of each substep's
  // end force f, `weight` x f).
  auto add_slow_contact = [&](double weight, bool now) {
#pragma omp parallel for schedule(static) if (threaded(s))
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (fast[P.body[i]]) continue;
      const Eigen::Vector3d f = now ? contact_density(s, i)
                                    : Eigen::Vector3d(s.contact_force[0][i], s.contact_force[1][i],
                                                      s.contact_force[2][i]);
      for (int d = 0; d < 3; ++d) s.contact_kick[d][i] += weight * f[d];
    }
  };
  auto clear_slow_contact = [&] {
    for (int d = 0; d < 3; ++d) std::fill(s.contact_kick[d].begin(), s.contact_kick[d].end(), 0.0);
  };

  // The slow bodies' v^{n+1/2}, with their last contact force f_0 over half the step, as velocity
  // Verlet has it; the second kick takes back what that is more than the fast bodies' dt/2 f_0.
  set_advancing(s, fast, false);
  clear_slow_contact();
  add_slow_contact(0.5 * step, /*now=*/false);
  kick(s, t0 + 0.5 * step, &s.contact_kick);
  clear_slow_contact();
  add_slow_contact(0.5 * (substep - step), /*now=*/false);
  s.dt = substep;
  for (int k = 1; k <= substeps; ++k) {
    set_advancing(s, fast, true);
    kick(s, t0 + (k - 0.5) * substep);
    move(s);
    s.time = t0 + k * substep;
    complete(s, s.time);
    add_contact_impulses(s);
    add_slow_contact(k < substeps ? substep : 0.5 * substep, /*now=*/true);
  }
  s.dt = step;
  s.time = t0 + step;
  set_advancing(s, fast, false);
  complete(s, s.time, &s.contact_kick);
  std::fill(s.advancing.begin(), s.advancing.end(), 1);
}

}  // namespace

double stable_time_step(const State& s, double cfl) {
  if (!s.settings.subcycling) return cfl * s.min_spacing / s.max_signal_speed;
  // The largest body's own step, within kMaxSubsteps of every other's.
  double shortest = own_step(s, 0);
  for (std::size_t b = 1; b < s.bodies.size(); ++b) shortest = std::min(shortest, own_step(s, b));
  return cfl / s.cfl * std::min(own_step(s, largest_body(s)), kMaxSubsteps * shortest);
}

void step(State& s) {
  for (auto& impulse : s.contact_impulse) impulse = {0.0, 0.0, 0.0};
  std::vector<std::uint8_t>& fast = s.fast_bodies;
  s.substeps = s.settings.subcycling ? plan_substeps(s, fast) : 1;
  if (s.substeps > 1) {
    subcycled_step(s, fast, s.substeps);
  } else {
    kick(s, s.time + 0.5 * s.dt);  // v^{n+1/2}
    move(s);                       // x^{n+1}
    complete(s, s.time + s.dt);
    add_contact_impulses(s);
    s.time += s.dt;
  }
  ++s.step;
  bodies::track_penetration(s);  // bonding's activation, reported for both solvers
}

}  // namespace coldspray::pd
