#include "bodies/seed_bodies.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "bodies/material_state.hpp"
#include "case/located_error.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::bodies {

namespace {

using case_file::Vec3;

std::string body_key(const case_file::Body& b, const char* field) {
  return fmt::format("bodies.{}.{}", b.name, field);
}

// Body a's points are tested against body b's shape only where the shape meets the box of a's
// points: a deposit's particles meet few of the others, and testing every point of every body
// against every other shape took N^2 x points for N bodies.
void check_no_overlap(const case_file::Case& c, const std::vector<SeededBody>& seeded) {
  for (std::size_t a = 0; a < seeded.size(); ++a)
    for (std::size_t b = 0; b < seeded.size(); ++b) {
      if (a == b || !geometry::meets(c.bodies[b].shape, {seeded[a].min, seeded[a].max})) continue;
      stop_set_up_if_interrupted("checking that the bodies do not overlap");
      for (const Vec3& x : seeded[a].points.position)
        if (geometry::contains(c.bodies[b].shape, x))
          case_file::fail_at(c, body_key(c.bodies[a], "shape"),
                             fmt::format("body '{}' overlaps body '{}' at t = 0", c.bodies[a].name,
                                         c.bodies[b].name));
    }
}

// A body's diameter across the impact axis at t = 0, for the flattening ratio: the x extent of
// its points plus one spacing, the points mirrored at a symmetry plane normal to x if it was cut
// there (in r-z, twice the largest radius plus one spacing).
double lateral_diameter(const std::vector<Vec3>& points, double spacing,
                        std::optional<double> mirror_plane) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (const Vec3& x : points) {
    lo = std::min(lo, x[0]);
    hi = std::max(hi, x[0]);
  }
  if (mirror_plane) return 2.0 * std::max(hi - *mirror_plane, *mirror_plane - lo) + spacing;
  return hi - lo + spacing;
}

std::uint8_t face_bits(case_file::BodyFace f) {
  using namespace geometry;
  switch (f) {
    case case_file::BodyFace::Bottom:
      return kMinusZ;
    case case_file::BodyFace::Top:
      return kPlusZ;
    case case_file::BodyFace::Side:
      return kMinusX | kPlusX | kMinusY | kPlusY;
  }
  return 0;
}

// Eqs 3.45-3.46 with a = b = 1: along the face normal a dashpot rho c_p per unit area, along
// the face's tangents rho c_s. A point with outside neighbours along several axes (an edge)
// adds up one face area per such neighbour.
AbsorbingPoint absorbing_point(const BodyRange& body, std::size_t p, const Points& P,
                               std::uint8_t outside, bool axi) {
  const materials::Material& m = body.material;
  const double rho = m.density, G = m.elastic.shear_modulus, K = m.elastic.bulk_modulus;
  const double cp = std::sqrt((K + 4.0 / 3.0 * G) / rho), cs = std::sqrt(G / rho);
  const double s = body.spacing;
  const double face_area = axi ? 2.0 * std::numbers::pi * P.position[0][p] * s : s * s;
  double area[3] = {0, 0, 0};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      if (outside & (1u << (2 * axis + side))) area[axis] += face_area;
  const double total = area[0] + area[1] + area[2];
  AbsorbingPoint a;
  a.point = p;
  for (int d = 0; d < 3; ++d) a.damping[d] = rho * (cp * area[d] + cs * (total - area[d]));
  if (axi) a.damping[1] = 0.0;  // no hoop motion in r-z
  return a;
}

}  // namespace

void SeededBody::bound() {
  min = Vec3::Constant(std::numeric_limits<double>::max());
  max = -min;
  for (const Vec3& x : points.position) {
    min = min.cwiseMin(x - Vec3::Constant(0.5 * spacing));
    max = max.cwiseMax(x + Vec3::Constant(0.5 * spacing));
  }
}

std::vector<SeededBody> seed_bodies(const case_file::Case& c) {
  const bool axi = c.solver.geometry == case_file::Geometry::Axisymmetric;
  std::vector<SeededBody> seeded;
  for (const case_file::Body& b : c.bodies) {
    stop_set_up_if_interrupted("seeding the bodies");
    SeededBody sd;
    sd.spacing = b.spacing;
    const geometry::Lattice lattice{Vec3::Zero(), b.spacing, axi};
    sd.points = b.coarsening ? geometry::seed_coarsened(b.shape, lattice, b.coarsening->levels,
                                                        b.coarsening->fine)
                             : geometry::seed(b.shape, lattice);
    if (sd.points.position.empty())
      case_file::fail_at(
          c, body_key(b, "spacing"),
          fmt::format("body '{}' has no points: its spacing is larger than its shape", b.name));
    sd.bound();
    seeded.push_back(std::move(sd));
  }
  check_no_overlap(c, seeded);
  return seeded;
}

void cut_at_planes(const case_file::Case& c, const std::vector<CutPlane>& planes,
                   const char* planes_name, std::vector<SeededBody>& seeded) {
  for (std::size_t b = 0; b < seeded.size(); ++b) {
    SeededBody& sd = seeded[b];
    geometry::SeededPoints kept;
    for (std::size_t i = 0; i < sd.points.position.size(); ++i) {
      const Vec3& x = sd.points.position[i];
      bool inside = true;
      for (const CutPlane& plane : planes) {
        if (plane.keep_above ? x[plane.axis] >= plane.position : x[plane.axis] <= plane.position)
          continue;
        inside = false;
        if (plane.axis < 2) sd.mirror_plane[plane.axis] = plane.position;
      }
      if (!inside) continue;
      kept.position.push_back(x);
      kept.volume.push_back(sd.points.volume[i]);
      kept.size.push_back(sd.points.size[i]);
      kept.outside.push_back(sd.points.outside[i]);
    }
    if (kept.position.empty())
      case_file::fail_at(
          c, body_key(c.bodies[b], "shape"),
          fmt::format("body '{}' lies wholly beyond {}", c.bodies[b].name, planes_name));
    sd.points = std::move(kept);
    sd.bound();
  }
}

std::uint8_t faces_bits(const std::vector<case_file::BodyFace>& faces) {
  std::uint8_t bits = 0;
  for (auto f : faces) bits |= face_bits(f);
  return bits;
}

void lay_out_bodies(const case_file::Case& c, const std::vector<SeededBody>& seeded, Bodies& s) {
  s.geometry = c.solver.geometry;
  const bool axi = c.solver.geometry == case_file::Geometry::Axisymmetric;
  std::size_t total = 0;
  for (const SeededBody& sd : seeded) total += sd.points.position.size();
  Points& P = s.points;
  P.resize(total);
  std::size_t p = 0;
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const case_file::Body& body = c.bodies[b];
    BodyRange range{body.name, p, p + seeded[b].points.position.size(),
                    c.materials.at(body.material), body.spacing};
    range.initial_velocity = {body.velocity[0], body.velocity[1], body.velocity[2]};
    range.mirror_plane = seeded[b].mirror_plane;
    if (axi) range.mirror_plane[0] = 0.0;
    range.initial_diameter =
        lateral_diameter(seeded[b].points.position, body.spacing, range.mirror_plane[0]);
    const materials::PointState initial =
        materials::initial_state(range.material, body.temperature);
    const double c0 = materials::wave_speed(range.material, initial);
    for (std::size_t i = 0; i < seeded[b].points.position.size(); ++i, ++p) {
      for (int d = 0; d < 3; ++d) {
        P.position[d][p] = seeded[b].points.position[i][d];
        P.velocity[d][p] = body.velocity[d];
      }
      P.volume0[p] = seeded[b].points.volume[i];
      P.mass[p] = range.material.density * P.volume0[p];
      for (int d = 0; d < 3; ++d) P.half_width[d][p] = 0.5 * seeded[b].points.size[i];
      store_point_state(initial, P, p);
      P.sound_speed[p] = c0;
      P.body[p] = static_cast<std::uint16_t>(b);
      P.surface[p] = seeded[b].points.outside[i] != 0;
      P.initial_z[p] = P.position[2][p];
      P.id[p] = static_cast<std::uint32_t>(i);
    }
    s.bodies.push_back(std::move(range));
  }
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const std::uint8_t absorbing = faces_bits(c.bodies[b].absorbing);
    for (std::size_t i = 0; i < seeded[b].points.outside.size(); ++i) {
      const std::uint8_t outside = seeded[b].points.outside[i] & absorbing;
      if (outside)
        s.absorbing.push_back(absorbing_point(s.bodies[b], s.bodies[b].begin + i, P, outside, axi));
    }
  }
  s.contact_impulse.assign(c.bodies.size() * c.bodies.size(), {0.0, 0.0, 0.0});
  s.impact_metrics = c.metrics;
  for (std::size_t q = 0; q < total; ++q) {
    const double speed =
        std::sqrt(P.velocity[0][q] * P.velocity[0][q] + P.velocity[1][q] * P.velocity[1][q] +
                  P.velocity[2][q] * P.velocity[2][q]);
    s.max_signal_speed = std::max(s.max_signal_speed, P.sound_speed[q] + speed);
  }
  start_penetration(s);
}

}  // namespace coldspray::bodies
