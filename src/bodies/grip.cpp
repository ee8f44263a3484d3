#include "bodies/grip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace coldspray::bodies {

void prepare_grip(Bodies& s, const std::optional<case_file::Grip>& grip) {
  s.gripped.assign(s.points.size(), 0);
  if (grip) s.grip_velocity = grip->velocity, s.grip_ramp = grip->ramp;
}

Eigen::Vector3d grip_velocity_at(const Bodies& s, double t) {
  if (t >= s.grip_ramp) return s.grip_velocity;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * t / s.grip_ramp)) * s.grip_velocity;
}

void take_grip(Bodies& s, const case_file::Grip& grip) {
  Points& P = s.points;
  for (int d = 0; d < 3; ++d) std::fill(P.velocity[d].begin(), P.velocity[d].end(), 0.0);
  const auto body = std::find_if(s.bodies.begin(), s.bodies.end(),
                                 [&](const BodyRange& b) { return b.name == grip.body; });
  const Eigen::Vector3d side = (grip.side.norm() > 0.0 ? grip.side : grip.velocity).normalized();
  auto along = [&](std::size_t i) {
    return side.dot(Eigen::Vector3d(P.position[0][i], P.position[1][i], P.position[2][i]));
  };
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (std::size_t i = body->begin; i < body->end; ++i) {
    lo = std::min(lo, along(i));
    hi = std::max(hi, along(i));
  }
  const double from = grip.fraction >= 1.0 ? lo : hi - grip.fraction * (hi - lo);
  // The box the gripped points span: no point of another body may lie in it.
  Eigen::Vector3d box_lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d box_hi = Eigen::Vector3d::Constant(std::numeric_limits<double>::lowest());
  auto position = [&](std::size_t i) {
    return Eigen::Vector3d(P.position[0][i], P.position[1][i], P.position[2][i]);
  };
  for (std::size_t i = body->begin; i < body->end; ++i)
    if (along(i) >= from) {
      box_lo = box_lo.cwiseMin(position(i));
      box_hi = box_hi.cwiseMax(position(i));
    }
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (i >= body->begin && i < body->end) continue;
    const Eigen::Vector3d x = position(i);
    if ((x.array() >= box_lo.array()).all() && (x.array() <= box_hi.array()).all())
      throw InputError(
          "", "grip.fraction",
          fmt::format("the grip of '{}' would take in points of '{}' (one at [{:.4g}, {:.4g}, "
                      "{:.4g}] um lies among the gripped points): grip a smaller part of the "
                      "body (coldspray pull-off --grip)",
                      grip.body, s.bodies[P.body[i]].name, x[0] * 1e6, x[1] * 1e6, x[2] * 1e6));
  }
  std::fill(s.gripped.begin(), s.gripped.end(), 0);
  const Eigen::Vector3d v = grip_velocity_at(s, s.time);
  for (std::size_t i = body->begin; i < body->end; ++i)
    if (along(i) >= from) {
      s.gripped[i] = 1;
      for (int d = 0; d < 3; ++d) P.velocity[d][i] = v[d];
    }
}

}  // namespace coldspray::bodies
