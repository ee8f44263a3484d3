#include "bodies/grip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "bodies/body_axis.hpp"
#include "bodies/splat_piece.hpp"
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

namespace {

Eigen::Vector3d position(const Points& P, std::size_t i) {
  return {P.position[0][i], P.position[1][i], P.position[2][i]};
}

// The first point of another body within the box that the body's points `taken` span, if any.
template <class Taken>
std::optional<std::size_t> other_point_in_box(const Bodies& s, const BodyRange& body,
                                              Taken&& taken) {
  const Points& P = s.points;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = body.begin; i < body.end; ++i)
    if (taken(i)) {
      lo = lo.cwiseMin(position(P, i));
      hi = hi.cwiseMax(position(P, i));
    }
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (i >= body.begin && i < body.end) continue;
    const Eigen::Vector3d x = position(P, i);
    if ((x.array() >= lo.array()).all() && (x.array() <= hi.array()).all()) return i;
  }
  return std::nullopt;
}

// Where the last `fraction` of the extent along `side` of the body's points `taken` starts.
template <class Taken>
double far_share_start(const Points& P, const BodyRange& body, const Eigen::Vector3d& side,
                       double fraction, Taken&& taken) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (std::size_t i = body.begin; i < body.end; ++i)
    if (taken(i)) {
      lo = std::min(lo, side.dot(position(P, i)));
      hi = std::max(hi, side.dot(position(P, i)));
    }
  return fraction >= 1.0 ? lo : hi - fraction * (hi - lo);
}

}  // namespace

void take_grip(Bodies& s, const case_file::Grip& grip) {
  Points& P = s.points;
  for (int d = 0; d < 3; ++d) {  // at rest: no velocity, and no motion over a last step
    std::fill(P.velocity[d].begin(), P.velocity[d].end(), 0.0);
    std::fill(P.displacement[d].begin(), P.displacement[d].end(), 0.0);
  }
  const BodyRange& body = *std::find_if(s.bodies.begin(), s.bodies.end(),
                                        [&](const BodyRange& b) { return b.name == grip.body; });
  const Eigen::Vector3d side = (grip.side.norm() > 0.0 ? grip.side : grip.velocity).normalized();
  auto along = [&](std::size_t i) { return side.dot(position(P, i)); };
  // The splat, not drops it shed: above a 22 um splat at 1000-1300 m/s they stretched the
  // body's extent to 3 times the splat's, and its last 30 % held only them
  // (docs/validation/bond-strength.md).
  const std::vector<char> splat = splat_piece(P, body);
  auto in_splat = [&](std::size_t i) { return splat[i - body.begin] != 0; };
  const double from = far_share_start(P, body, side, grip.fraction, in_splat);
  auto upper = [&](std::size_t i) { return in_splat(i) && along(i) >= from; };
  // Where the upper part's box takes in another body's points (a splat whose jetted rim folds up
  // over the crater's lip), only its core: the splat's points within the body's initial radius
  // of its axis, in the last `fraction` of the core's own extent. (A flat splat's rim rises above
  // its centre: at 1300 m/s the last 30 % of the 22 um splat's extent held only its rim, beyond
  // that radius.)
  const Eigen::Vector3d axis = axis_point(P, body);  // (bodies/body_axis.hpp)
  auto in_core = [&](std::size_t i) {
    const Eigen::Vector3d r = position(P, i) - axis;
    return in_splat(i) && (r - r.dot(side) * side).norm() <= 0.5 * body.initial_diameter;
  };
  const double core_from = far_share_start(P, body, side, grip.fraction, in_core);
  auto core = [&](std::size_t i) { return in_core(i) && along(i) >= core_from; };
  const bool whole = !other_point_in_box(s, body, upper);
  if (!whole)
    if (const auto clash = other_point_in_box(s, body, core)) {
      const Eigen::Vector3d x = position(P, *clash);
      throw InputError(
          "", "grip.fraction",
          fmt::format("the grip of '{}' would take in points of '{}' (one at [{:.4g}, {:.4g}, "
                      "{:.4g}] um lies among the gripped points, even within the body's initial "
                      "radius of its axis): grip a smaller part of the body (coldspray pull-off "
                      "--grip)",
                      grip.body, s.bodies[P.body[*clash]].name, x[0] * 1e6, x[1] * 1e6,
                      x[2] * 1e6));
    }
  std::fill(s.gripped.begin(), s.gripped.end(), 0);
  const Eigen::Vector3d v = grip_velocity_at(s, s.time);
  std::size_t taken = 0;
  for (std::size_t i = body.begin; i < body.end; ++i)
    if (whole ? upper(i) : core(i)) {
      s.gripped[i] = 1, ++taken;
      for (int d = 0; d < 3; ++d) P.velocity[d][i] = v[d];
    }
  if (taken == 0)
    throw InputError("", "grip.fraction",
                     fmt::format("the grip of '{}' takes none of its points: no point of its "
                                 "splat lies within its initial radius of its axis",
                                 grip.body));
}

}  // namespace coldspray::bodies
