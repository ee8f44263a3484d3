#include "run/interface_areas.hpp"

#include <cmath>
#include <numbers>

#include "bodies/body_axis.hpp"
#include "bodies/point_area.hpp"
#include "bonding/cohesive_law.hpp"
#include "metrics/impact_metrics.hpp"
#include "run/checkpoints.hpp"
#include "run/solver.hpp"

namespace coldspray::run {

namespace {

// The body's bonded points with the strength the debonding law gives each
// (bonding/cohesive_law.hpp), radii from its impact axis (bodies/body_axis.hpp; r = x in r-z).
std::vector<InterfacePoint> bonded_points(const case_file::Case& c, const bodies::Bodies& s,
                                          std::size_t body) {
  const bonding::CohesiveLaw law = bonding::CohesiveLaw::from_case(c.bonding);
  const bodies::Points& P = s.points;
  const bodies::BodyRange& r = s.bodies[body];
  const bool axi = s.geometry == case_file::Geometry::Axisymmetric;
  const Eigen::Vector3d axis = bodies::axis_point(P, r);
  std::vector<InterfacePoint> out;
  for (std::size_t p = r.begin; p < r.end; ++p) {
    if (P.bonded_to[p] == 0) continue;
    InterfacePoint q;
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

InterfaceAreas interface_areas(const case_file::Case& c, const std::filesystem::path& file,
                               std::size_t body) {
  SolverState state = build_solver_state(c);
  return std::visit(
      [&](auto& s) {
        load_initial_state(file, s);
        InterfaceAreas a;
        // The footprint's diameter: the flattening ratio's 2 r + h = ratio x initial diameter.
        const double d =
            metrics::impact_measures(s, body, metrics::SplatExtent::Measured).flattening_ratio *
            s.bodies[body].initial_diameter;
        a.projected = std::numbers::pi * d * d / 4.0;
        a.mirror_plane = s.bodies[body].mirror_plane;
        a.axisymmetric = s.geometry == case_file::Geometry::Axisymmetric;
        if (c.solver.method == case_file::Method::Mpm) {
          a.bonded = metrics::rest_and_bond(s, body).bonded_area;
          if (c.bonding.debond.law == case_file::DebondLaw::Cohesive)
            a.points = bonded_points(c, s, body);
        } else {
          a.bonded = metrics::touching_area(s, body);
        }
        return a;
      },
      state);
}

}  // namespace coldspray::run
