#include "pd/grip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace coldspray::pd {

Eigen::Vector3d grip_velocity_at(const State& s, double t) {
  if (t >= s.grip_ramp) return s.grip_velocity;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * t / s.grip_ramp)) * s.grip_velocity;
}

void take_grip(State& s, const case_file::Grip& grip) {
  bodies::Points& P = s.points;
  for (int d = 0; d < 3; ++d) std::fill(P.velocity[d].begin(), P.velocity[d].end(), 0.0);
  const auto body = std::find_if(s.bodies.begin(), s.bodies.end(),
                                 [&](const bodies::BodyRange& b) { return b.name == grip.body; });
  const Eigen::Vector3d direction = grip.velocity.normalized();
  auto along = [&](std::size_t i) {
    return direction.dot(Eigen::Vector3d(P.position[0][i], P.position[1][i], P.position[2][i]));
  };
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (std::size_t i = body->begin; i < body->end; ++i) {
    lo = std::min(lo, along(i));
    hi = std::max(hi, along(i));
  }
  const double from = hi - grip.fraction * (hi - lo);
  std::fill(s.gripped.begin(), s.gripped.end(), 0);
  const Eigen::Vector3d v = grip_velocity_at(s, s.time);
  for (std::size_t i = body->begin; i < body->end; ++i)
    if (along(i) >= from) {
      s.gripped[i] = 1;
      for (int d = 0; d < 3; ++d) P.velocity[d][i] = v[d];
    }
}

}  // namespace coldspray::pd
