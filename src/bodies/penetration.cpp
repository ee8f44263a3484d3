#include "bodies/penetration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bodies/bodies.hpp"

namespace coldspray::bodies {

namespace {

// The body's mass-weighted centroid along `direction`, summed in point order.
double centroid_along(const Bodies& s, const BodyRange& r, const std::array<double, 3>& n) {
  const Points& P = s.points;
  double moment = 0.0, mass = 0.0;
  for (std::size_t p = r.begin; p < r.end; ++p) {
    moment +=
        P.mass[p] * (P.position[0][p] * n[0] + P.position[1][p] * n[1] + P.position[2][p] * n[2]);
    mass += P.mass[p];
  }
  return mass > 0.0 ? moment / mass : 0.0;
}

bool touched_this_step(const Bodies& s, std::size_t a) {
  const std::size_t n = s.bodies.size();
  for (std::size_t b = 0; b < n; ++b)
    for (const double j : s.contact_impulse[a * n + b])
      if (j != 0.0) return true;
  return false;
}

}  // namespace

void start_penetration(Bodies& s) {
  const Points& P = s.points;
  for (BodyRange& r : s.bodies) {
    Penetration& pen = r.penetration;
    pen = {};
    const std::array<double, 3>& v = r.initial_velocity;
    const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (speed == 0.0 || r.begin == r.end) continue;
    for (int d = 0; d < 3; ++d) pen.direction[d] = v[d] / speed;
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    for (std::size_t p = r.begin; p < r.end; ++p) {
      double x = 0.0;
      for (int d = 0; d < 3; ++d) x += P.position[d][p] * pen.direction[d];
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    pen.size = hi - lo + r.spacing;
    pen.last = centroid_along(s, r, pen.direction);
  }
}

void track_penetration(Bodies& s) {
  if (s.contact_impulse.size() != s.bodies.size() * s.bodies.size()) return;
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    BodyRange& r = s.bodies[a];
    Penetration& pen = r.penetration;
    const bool first = pen.first_contact < 0.0 && touched_this_step(s, a);
    if (first) pen.first_contact = s.time - s.dt;       // the step's start: the clock has advanced
    if (pen.size <= 0.0 || r.begin == r.end) continue;  // at rest, or gone: no penetration
    const double now = centroid_along(s, r, pen.direction);
    if (first) pen.start = pen.last;
    if (pen.first_contact >= 0.0) {
      pen.largest = std::max(pen.largest, (now - pen.start) / pen.size);
      if (pen.peak < 0.0 && now <= pen.last) pen.peak = s.time;
    }
    pen.last = now;
  }
}

bool pair_activated(const Penetration& a, const Penetration& b, double critical) {
  if (critical <= 0.0) return true;
  if (a.first_contact < 0.0 || b.first_contact < 0.0) return false;
  const Penetration& impact = a.first_contact > b.first_contact   ? a
                              : b.first_contact > a.first_contact ? b
                              : a.largest >= b.largest            ? a
                                                                  : b;
  return impact.largest >= critical;
}

}  // namespace coldspray::bodies
