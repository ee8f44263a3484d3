#include "metrics/impact_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "bodies/point_area.hpp"
#include "bodies/splat_piece.hpp"

namespace coldspray::metrics {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double point_area(const bodies::Bodies& s, std::size_t p) {
  return bodies::point_area(s.points, p, s.geometry == case_file::Geometry::Axisymmetric);
}

// The factor from the modelled part of a body to the whole: 2 per symmetry plane it was cut at
// in 3D (a quarter model counts 4); an r-z point already stands for its whole ring.
double whole_body_factor(const bodies::Bodies& s, const bodies::BodyRange& r) {
  if (s.geometry == case_file::Geometry::Axisymmetric) return 1.0;
  double factor = 1.0;
  for (const auto& plane : r.mirror_plane)
    if (plane) factor *= 2.0;
  return factor;
}

}  // namespace

RestAndBond rest_and_bond(const bodies::Bodies& s, std::size_t body) {
  const bodies::Points& P = s.points;
  const bodies::BodyRange& r = s.bodies[body];
  RestAndBond out;
  for (std::size_t p = r.begin; p < r.end; ++p) {
    out.mass += P.mass[p];
    out.momentum_z += P.mass[p] * P.velocity[2][p];
    if (bodies::speed(P, p) <= s.impact_metrics.rest_speed_limit) {
      out.rest_mass += P.mass[p];
      out.rest_momentum_z += P.mass[p] * P.velocity[2][p];
    }
    if (P.bonded_to[p] != 0) out.bonded_area += point_area(s, p);
  }
  out.bonded_area *= whole_body_factor(s, r);
  return out;
}

double touching_area(const bodies::Bodies& s, std::size_t body) {
  const bodies::BodyRange& r = s.bodies[body];
  double area = 0.0;
  for (std::size_t p = r.begin; p < r.end; ++p)
    if (s.points.touching[p]) area += point_area(s, p);
  return area * whole_body_factor(s, r);
}

ImpactMeasures impact_measures(const bodies::Bodies& s, std::size_t body, SplatExtent extent) {
  const bodies::Points& P = s.points;
  const bodies::BodyRange& r = s.bodies[body];
  ImpactMeasures m;
  m.moving = r.initial_velocity[2] != 0.0;

  double mass = 0.0, momentum_z = 0.0, centroid[2] = {0.0, 0.0}, volume0 = 0.0, plastic = 0.0;
  double top = std::numeric_limits<double>::lowest();
  for (std::size_t p = r.begin; p < r.end; ++p) {
    mass += P.mass[p];
    momentum_z += P.mass[p] * P.velocity[2][p];
    for (int d = 0; d < 2; ++d) centroid[d] += P.mass[p] * P.position[d][p];
    volume0 += P.volume0[p];
    plastic += P.plastic_work[p];
    top = std::max(top, P.initial_z[p]);
  }
  // The impact axis: the vertical through the body's centroid, which lies on a symmetry plane it
  // was cut at (in r-z, the axis r = 0).
  for (int d = 0; d < 2; ++d)
    centroid[d] = r.mirror_plane[d] ? *r.mirror_plane[d] : centroid[d] / mass;
  m.cor = m.moving ? -(momentum_z / mass) / r.initial_velocity[2] : kNaN;
  m.plastic_energy_density = plastic / volume0;

  // Jetting is judged in the frame that moves with the body along the axis, so that a particle's
  // rebound (or any motion of the whole body along z) is not taken for a jet.
  const double body_vz = momentum_z / mass;
  // The splat's extent leaves out drops the body shed (bodies/splat_piece.hpp).
  const std::vector<char> piece = extent == SplatExtent::Measured && m.moving
                                      ? bodies::splat_piece(P, r)
                                      : std::vector<char>(r.end - r.begin, 1);
  double jetted = 0.0, touched = 0.0, bonded = 0.0, bond_sum = 0.0, radius = 0.0;
  std::size_t touched_points = 0;
  m.bonded_area_with.assign(s.bodies.size(), 0.0);
  for (std::size_t p = r.begin; p < r.end; ++p) {
    const double dx = P.position[0][p] - centroid[0], dy = P.position[1][p] - centroid[1];
    const double radial = std::hypot(dx, dy);
    const bool outward = radial > 0.0 && P.velocity[0][p] * dx + P.velocity[1][p] * dy > 0.0;
    const double relative_speed =
        std::hypot(P.velocity[0][p], P.velocity[1][p], P.velocity[2][p] - body_vz);
    if (relative_speed > s.impact_metrics.rest_speed_limit && outward)
      jetted += P.mass[p];
    else if (piece[p - r.begin])
      radius = std::max(radius, radial);
    if (P.surface[p] && P.initial_z[p] > top - 0.75 * r.spacing)
      m.crater_depth = std::max(m.crater_depth, P.initial_z[p] - P.position[2][p]);
    // As bonded_area (rest_and_bond): every point that keeps a bond.
    if (P.bonded_to[p] != 0) m.bonded_area_with[P.bonded_to[p] - 1u] += point_area(s, p);
    if (!P.touched[p]) continue;
    ++touched_points;
    bond_sum += P.bond[p];
    m.contact_area += point_area(s, p);
    if (P.bond[p] > 0.0) touched += P.mass[p];
    if (P.bond[p] >= 1.0) bonded += P.mass[p];
  }
  const RestAndBond rest = rest_and_bond(s, body);
  m.v_rest = rest.rest_mass > 0.0 ? rest.rest_momentum_z / rest.rest_mass : kNaN;
  m.bonded_area = rest.bonded_area;
  m.contact_area *= whole_body_factor(s, r);
  m.jetted_fraction = (jetted + r.departed.mass) / (mass + r.departed.mass);
  m.flattening_ratio =
      extent == SplatExtent::Measured ? (2.0 * radius + r.spacing) / r.initial_diameter : kNaN;
  m.penetration = r.penetration.size > 0.0 ? r.penetration.largest : kNaN;
  m.penetration_peak_time = r.penetration.peak >= 0.0 ? r.penetration.peak : kNaN;
  m.abp = touched_points > 0 ? bond_sum / static_cast<double>(touched_points) : 0.0;
  m.pbcp = touched > 0.0 ? 100.0 * bonded / touched : 0.0;
  const double whole = whole_body_factor(s, r);
  for (double& area : m.bonded_area_with) area *= whole;
  m.contacted_mass = whole * touched;
  m.bonded_mass = whole * bonded;
  return m;
}

double system_pbcp(const std::vector<ImpactMeasures>& bodies) {
  double contacted = 0.0, bonded = 0.0;
  for (const ImpactMeasures& m : bodies) {
    contacted += m.contacted_mass;
    bonded += m.bonded_mass;
  }
  return contacted > 0.0 ? 100.0 * bonded / contacted : 0.0;
}

}  // namespace coldspray::metrics
