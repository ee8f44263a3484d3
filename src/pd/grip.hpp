// The rigid grip of the pull-off test (docs/pull-off.md; PD paper Fig 11: "the particle is
// rigidly displaced away from the substrate"). At the run's start every point is set at rest and
// the points of the gripped body in the last `fraction` of its extent along the grip's velocity
// are taken: from then on they move at that velocity (pd/stepper.cpp's kick), and the force that
// keeps them from accelerating is the grip's, whose work the budget books with the holds'.
#pragma once

#include "case/case.hpp"
#include "pd/state.hpp"

namespace coldspray::pd {

// The grip's velocity at time t: (1 - cos(pi t / ramp)) / 2 of its full velocity until the ramp
// ends, then all of it.
Eigen::Vector3d grip_velocity_at(const State& s, double t);

// Sets every point at rest and grips the body's points whose projection on the grip's direction
// lies in the last `fraction` of the body's range, which then move at the grip's velocity.
void take_grip(State& s, const case_file::Grip& grip);

}  // namespace coldspray::pd
