// The rigid grip of the pull-off test (docs/pull-off.md; PD paper Fig 11: "the particle is
// rigidly displaced away from the substrate"), for either solver. At the run's start every point
// is set at rest and the points of the gripped body in the last `fraction` of its extent along
// the grip's side (its velocity's direction unless set) are taken: from then on they move at the
// grip's velocity (the solver's kick, pd/stepper.cpp, or velocity update, mpm/phases.hpp), and
// the force that keeps them from accelerating is the grip's, whose work the budget books with the
// holds'.
#pragma once

#include "bodies/bodies.hpp"
#include "case/case.hpp"

namespace coldspray::bodies {

// Sizes the per-point grip flags (none taken) and keeps the case's grip velocity and ramp.
void prepare_grip(Bodies& s, const std::optional<case_file::Grip>& grip);

// The grip's velocity at time t: (1 - cos(pi t / ramp)) / 2 of its full velocity until the ramp
// ends, then all of it.
Eigen::Vector3d grip_velocity_at(const Bodies& s, double t);

// Sets every point at rest and grips the points of the body's splat (the piece that hangs
// together, bodies/splat_piece.hpp; not drops it shed) whose projection on the grip's side lies
// in the last `fraction` of the splat's range, which then move at the grip's velocity. Where a
// point of another body lies within the box those points span (a splat's jetted rim folded up
// over the crater's lip), the grip would drag it along through contact: only the splat's points
// within the body's initial radius of its axis, in the last `fraction` of their own range, are
// gripped then, and if the box of those still holds one, or there are none, InputError (key
// grip.fraction).
void take_grip(Bodies& s, const case_file::Grip& grip);

}  // namespace coldspray::bodies
