#include "mpm/answers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "bodies/body_axis.hpp"
#include "bodies/point_area.hpp"
#include "bonding/cohesive_law.hpp"
#include "case/size_estimate.hpp"
#include "metrics/impact_metrics.hpp"

namespace coldspray::mpm {

namespace {

// The body's bonded points with the strength the debonding law gives each
// (bonding/cohesive_law.hpp), radii from its impact axis (bodies/body_axis.hpp; r = x in r-z).
std::vector<metrics::InterfacePoint> bonded_points(const case_file::Case& c, const State& s,
                                                   std::size_t body) {
  const bonding::CohesiveLaw law = bonding::CohesiveLaw::from_case(c.bonding);
  const bodies::Points& P = s.points;
  const bodies::BodyRange& r = s.bodies[body];
  const bool axi = s.geometry == case_file::Geometry::Axisymmetric;
  const Eigen::Vector3d axis = bodies::axis_point(P, r);
  std::vector<metrics::InterfacePoint> out;
  for (std::size_t p = r.begin; p < r.end; ++p) {
    if (P.bonded_to[p] == 0) continue;
    metrics::InterfacePoint q;
    for (int d = 0; d < 3; ++d) q.position[d] = P.position[d][p];
    q.radius = std::hypot(q.position[0] - axis[0], q.position[1] - axis[1]);
    q.area = bodies::point_area(P, p, axi);
    q.bond = P.bond[p];
    q.damage = P.bond_damage[p];
    const double full = law.full_strength(P.flow_stress[p]);
    q.strength = bonding::traction_capacity(full * bonding::bonded_share(P.bond[p]), q.damage);
    q.critical_opening = 2.0 * law.fracture_energy / full;
    out.push_back(q);
  }
  return out;
}

}  // namespace

std::string describe_discretisation(Solver, const case_file::Case& c, double unit,
                                    std::string_view symbol) {
  const std::array<double, 3> nodes = case_file::estimated_grid_nodes(c);
  return fmt::format("  MPM, grid cell {:.4g} {}, ~{:.3g} nodes\n", c.grid->cell_size / unit,
                     symbol, nodes[0] * nodes[1] * nodes[2]);
}

bool holds_bonds(Solver, const case_file::Case& c) {
  return c.bonding.model != case_file::BondingModel::None;
}

std::string_view unbonded_reason(Solver) {
  return "was run without bonding (bonding.model: none): no bond holds the splat to pull off";
}

// Its default, bonds that hold for good, is the shipped calibration's: that model decides the
// verdict, the debonding law the strength (docs/pull-off.md). The impact's own law and its
// parameters, where it set them, carry over.
void debond_during_pull(Solver, case_file::Case& c) {
  if (c.bonding.model != case_file::BondingModel::None)
    c.bonding.debond.law = case_file::DebondLaw::Cohesive;
}

// As the PD's substrate is held in its impact: the absorbing dashpots of the impact would let
// the substrate follow the grip.
void hold_for_pull(Solver, case_file::Case& c, std::size_t pulled) {
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (b == pulled) continue;
    auto& absorbing = c.bodies[b].absorbing;
    const auto bottom = std::find(absorbing.begin(), absorbing.end(), case_file::BodyFace::Bottom);
    if (bottom == absorbing.end()) continue;
    absorbing.erase(bottom);
    c.bodies[b].fixed.push_back(case_file::BodyFace::Bottom);
  }
}

// Twice the opening its bonds let go at, the debonding law's delta_c (the mean of the bonded
// points that carry a traction) but at most two cells, as the grid sees an opening only while
// both bodies share nodes, plus two cells.
double default_pull_distance(Solver, const case_file::Case& c, std::size_t /*body*/,
                             const metrics::InterfaceAreas& areas) {
  const double cell = c.grid->cell_size;
  double opening = 0.0, area = 0.0;
  for (const metrics::InterfacePoint& q : areas.points) {
    if (!(q.strength > 0.0)) continue;  // carries nothing (a melted point's flow stress is 0)
    opening += q.area * q.critical_opening;
    area += q.area;
  }
  return (area > 0.0 ? 2.0 * std::min(opening / area, 2.0 * cell) : 0.0) + 2.0 * cell;
}

void measure_bonds(const case_file::Case& c, const State& s, std::size_t body,
                   metrics::InterfaceAreas& areas) {
  areas.bonded = metrics::rest_and_bond(s, body).bonded_area;
  if (c.bonding.debond.law == case_file::DebondLaw::Cohesive)
    areas.points = bonded_points(c, s, body);
}

}  // namespace coldspray::mpm
