#include "case/size_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "case/field_rules.hpp"
#include "case/grid_domain.hpp"
#include "geometry/shape.hpp"
#include "materials/conduction_step.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::case_file {

namespace {

struct Extent {
  double volume;   // m^3
  double section;  // m^2, the r-z half-section (x >= 0)
};

Extent extent(const geometry::Shape& shape) {
  using std::numbers::pi;
  if (const auto* s = std::get_if<geometry::Sphere>(&shape))
    return {4.0 / 3.0 * pi * std::pow(s->radius, 3), 0.5 * pi * s->radius * s->radius};
  if (const auto* c = std::get_if<geometry::Cylinder>(&shape))
    return {pi * c->radius * c->radius * c->height, c->radius * c->height};
  const auto& b = std::get<geometry::Box>(shape);
  const Vec3 size = b.max - b.min;
  return {size.prod(), std::max(0.0, b.max.x() - std::max(b.min.x(), 0.0)) * size.z()};
}

// The MPM grid's domain, from the bodies' bounding boxes.
std::pair<Vec3, Vec3> estimated_grid_domain(const Case& c) {
  Vec3 lo = Vec3::Constant(kInfinity), hi = -lo;
  for (const Body& b : c.bodies) {
    const geometry::Bounds box = geometry::bounding_box(b.shape);
    lo = lo.cwiseMin(box.min);
    hi = hi.cwiseMax(box.max);
  }
  return grid_domain(c, lo, hi);
}

// A plane that cuts the bodies, keeping what lies above it (or below) along an axis.
struct CutPlane {
  int axis;
  double position;
  bool keep_above;
};

// Where the solver cuts the bodies in 3D: peridynamics at symmetry.x and .y, the MPM at its grid's
// fixed and roller faces (a quarter model keeps a quarter of a particle's points).
std::vector<CutPlane> cut_planes(const Case& c) {
  std::vector<CutPlane> planes;
  if (c.solver.method == Method::Peridynamics) {
    if (c.symmetry && c.symmetry->x) planes.push_back({0, *c.symmetry->x, true});
    if (c.symmetry && c.symmetry->y) planes.push_back({1, *c.symmetry->y, true});
    return planes;
  }
  const auto [lo, hi] = estimated_grid_domain(c);
  for (const auto& [face, condition] : c.grid->faces) {
    if (condition == FaceCondition::Free) continue;
    const int axis = static_cast<int>(face) / 2;
    const bool at_max = static_cast<int>(face) % 2 == 1;
    planes.push_back({axis, at_max ? hi[axis] : lo[axis], !at_max});
  }
  return planes;
}

}  // namespace

double estimated_points(const Case& c, const Body& b) {
  const Extent e = extent(b.shape);
  if (c.solver.geometry == Geometry::Axisymmetric) return e.section / std::pow(b.spacing, 2);
  const geometry::Bounds box = geometry::bounding_box(b.shape);
  const Vec3 size = box.max - box.min;
  double kept = 1.0;
  for (const CutPlane& plane : cut_planes(c)) {
    const int a = plane.axis;
    const double part =
        plane.keep_above ? box.max[a] - plane.position : plane.position - box.min[a];
    kept *= std::clamp(part / size[a], 0.0, 1.0);
  }
  return kept * lattice_points(b.shape, b.spacing);
}

double lattice_points(const geometry::Shape& shape, double spacing) {
  return extent(shape).volume / std::pow(spacing, 3);
}

std::array<double, 3> estimated_grid_nodes(const Case& c) {
  const double h = c.grid->cell_size;
  const bool axi = c.solver.geometry == Geometry::Axisymmetric;
  const auto [lo, hi] = estimated_grid_domain(c);
  std::array<double, 3> nodes{};
  for (int d = 0; d < 3; ++d)
    nodes[d] = std::ceil(hi[d] / h - 1e-9) - std::floor(lo[d] / h + 1e-9) + 3.0;
  if (axi) nodes[1] = 1.0;
  return nodes;
}

FirstStep first_time_step(const Case& c) {
  FirstStep first;
  double diffusivity = 0.0, finest = kInfinity;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    const materials::Material& m = c.materials.at(b.material);
    const double speed =
        materials::wave_speed(m, materials::initial_state(m, b.temperature)) + b.velocity.norm();
    if (!(speed <= first.signal_speed)) first = {0.0, i, speed};
    diffusivity =
        std::max(diffusivity, m.thermal.conductivity / (m.density * m.thermal.specific_heat));
    finest = std::min(finest, b.spacing);
  }
  const bool mpm = c.solver.method == Method::Mpm;
  const double h = mpm ? c.grid->cell_size : finest;
  first.dt = c.solver.dt_scale.value_or(c.solver.cfl) * h / first.signal_speed;
  if (mpm && c.solver.heat_conduction && diffusivity > 0.0)
    first.dt = std::min(first.dt, materials::conduction_step_limit(
                                      h, c.solver.geometry == Geometry::Axisymmetric, diffusivity));
  return first;
}

}  // namespace coldspray::case_file
