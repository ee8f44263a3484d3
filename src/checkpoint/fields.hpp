// What a run carries from one step to the next, field by field: everything a checkpoint saves
// so that a restarted run continues bit for bit as the uninterrupted one (docs/reliability.md).
// What a step recomputes before it reads it (the MPM's grid, the PD's F, its fits and force
// densities) is not saved; what it carries is (the points, the bodies' ledgers, the clock, the
// last signal speed that sets the next dt; for PD the accelerations of velocity Verlet, the
// control's accumulated force and history, and the contact list with its build positions,
// whose order fixes the contact forces' sums). setup builds the rest from the case.
#pragma once

#include <cstddef>
#include <string>

#include "bodies/bodies.hpp"
#include "checkpoint/archive.hpp"
#include "mpm/state.hpp"
#include "pd/state.hpp"

namespace coldspray::checkpoint {

template <class Archive>
void fields(Archive& a, bodies::Departed& d, const std::string& at) {
  a(at + "points", d.points), a(at + "mass", d.mass), a(at + "momentum", d.momentum);
  a(at + "kinetic", d.kinetic), a(at + "internal", d.internal);
  a(at + "plastic_work", d.plastic_work), a(at + "viscous_work", d.viscous_work);
  a(at + "contact_work", d.contact_work), a(at + "absorbed", d.absorbed);
}

// The solver-neutral part: points, body ranges and ledgers, absorbing points, clock.
template <class Archive>
void fields(Archive& a, bodies::Bodies& s) {
  s.points.for_each_named_array([&](const std::string& name, auto& v) {
    // Absent from checkpoints before the debonding law (2026-12-05), whose bonds were intact.
    if (name == "bond_damage")
      a.optional("points/" + name, v);
    else
      a("points/" + name, v);
  });
  if constexpr (Archive::kReading)
    if (s.points.bond_damage.size() != s.points.size())
      s.points.bond_damage.assign(s.points.size(), 0.0);
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const std::string at = "bodies/" + std::to_string(b) + "/";
    a(at + "begin", s.bodies[b].begin), a(at + "end", s.bodies[b].end);
    fields(a, s.bodies[b].departed, at + "departed/");
    // Absent from checkpoints before bonding's activation (2026-12-06): such a run continues as
    // if its bodies touched first at the restart.
    bodies::Penetration& pen = s.bodies[b].penetration;
    a.optional(at + "penetration/first_contact", pen.first_contact);
    a.optional(at + "penetration/start", pen.start);
    a.optional(at + "penetration/last", pen.last);
    a.optional(at + "penetration/largest", pen.largest);
    a.optional(at + "penetration/peak", pen.peak);
  }
  std::vector<std::size_t> point(s.absorbing.size());
  std::vector<std::array<double, 3>> damping(s.absorbing.size());
  std::vector<double> absorbed(s.absorbing.size());
  for (std::size_t k = 0; k < s.absorbing.size(); ++k)
    point[k] = s.absorbing[k].point, damping[k] = s.absorbing[k].damping,
    absorbed[k] = s.absorbing[k].absorbed;
  a("absorbing/point", point), a("absorbing/damping", damping), a("absorbing/absorbed", absorbed);
  if constexpr (Archive::kReading) {
    s.absorbing.resize(point.size());
    for (std::size_t k = 0; k < s.absorbing.size(); ++k)
      s.absorbing[k] = {point[k], damping[k], absorbed[k]};
  }
  a("contact_impulse", s.contact_impulse);
  a("clock/time", s.time), a("clock/dt", s.dt), a("clock/step", s.step);
  a("clock/max_signal_speed", s.max_signal_speed);
}

// The MPM carries nothing but the bodies (and a grip's hold) from step to step: each step builds
// its grid afresh from the points (thesis steps 1-2) and resets it at its end (step 12).
template <class Archive>
void fields(Archive& a, mpm::State& s) {
  fields(a, static_cast<bodies::Bodies&>(s));
  // The pull-off test's grip (bodies/grip.hpp); absent from checkpoints before the MPM's
  // (2026-12-05), whose runs had none.
  a.optional("mpm/gripped", s.gripped);
  if constexpr (Archive::kReading) {
    if (s.gripped.size() != s.points.size()) s.gripped.assign(s.points.size(), 0);
    // A checkpoint is written after a step, whose dt its clock holds: the step the points'
    // displacements span (the absorbing dashpots' velocity, mpm/boundaries.hpp).
    s.displacement_dt = s.step > 0 ? s.dt : 0.0;
  }
}

template <class Archive>
void fields(Archive& a, pd::State& s) {
  fields(a, static_cast<bodies::Bodies&>(s));
  axes(a, "pd/acceleration", s.acceleration);
  axes(a, "pd/control_force", s.control_force);
  a("pd/control_displacement", s.control_displacement);
  a("pd/contact/begin", s.contact.begin), a("pd/contact/other", s.contact.other);
  a("pd/contact/built_at", s.contact.built_at), a("pd/contact/builds", s.contact.builds);
  a("pd/contact/largest_stretch", s.contact.largest_stretch);
  a("pd/gripped", s.gripped);
  // Subcycling's: each body's signal speed, which sets its substeps, and the last contact force
  // density, which a slow body's first kick takes. Absent from checkpoints before it
  // (2026-12-05), whose runs read neither between steps.
  a.optional("pd/body_signal_speed", s.body_signal_speed);
  for (int d = 0; d < 3; ++d)
    a.optional(std::string("pd/contact_force_") + "xyz"[d], s.contact_force[d]);
}

}  // namespace coldspray::checkpoint
