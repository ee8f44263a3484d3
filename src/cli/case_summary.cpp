#include "cli/case_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>

namespace coldspray::cli {

namespace {

struct ShapeDescription {
  std::string text;
  double volume;   // m^3, for the point-count estimate in 3D
  double section;  // m^2, the r-z half-section (x >= 0), for the estimate in r-z
};

ShapeDescription describe(const case_file::Shape& shape) {
  using std::numbers::pi;
  if (const auto* s = std::get_if<case_file::Sphere>(&shape))
    return {fmt::format("sphere r = {:.4g} um", s->radius * 1e6),
            4.0 / 3.0 * pi * std::pow(s->radius, 3), 0.5 * pi * s->radius * s->radius};
  if (const auto* c = std::get_if<case_file::Cylinder>(&shape))
    return {fmt::format("cylinder r = {:.4g} um, h = {:.4g} um", c->radius * 1e6, c->height * 1e6),
            pi * c->radius * c->radius * c->height, c->radius * c->height};
  const auto& b = std::get<case_file::Box>(shape);
  const Eigen::Vector3d size = b.max - b.min;
  return {fmt::format("box {:.4g} x {:.4g} x {:.4g} um", size.x() * 1e6, size.y() * 1e6,
                      size.z() * 1e6),
          size.prod(), std::max(0.0, b.max.x() - std::max(b.min.x(), 0.0)) * size.z()};
}

}  // namespace

void print_case_summary(const case_file::Case& c, std::ostream& out) {
  const bool axisymmetric = c.solver.geometry == case_file::Geometry::Axisymmetric;
  out << fmt::format("case '{}': {}, {} bodies, end time {:.4g} ns\n", c.name,
                     axisymmetric ? "axisymmetric" : "3D", c.bodies.size(),
                     c.solver.end_time * 1e9);
  for (const auto& b : c.bodies) {
    const ShapeDescription shape = describe(b.shape);
    const double points = axisymmetric ? shape.section / std::pow(b.spacing, 2)
                                       : shape.volume / std::pow(b.spacing, 3);
    out << fmt::format("  body '{}': {}, material {}, spacing {:.4g} um, ~{:.3g} points\n", b.name,
                       shape.text, b.material, b.spacing * 1e6, points);
  }
  if (c.solver.method == case_file::Method::Peridynamics)
    out << fmt::format("  peridynamics, horizon {:.4g} x spacing\n",
                       c.peridynamics->horizon_factor);
  else
    out << fmt::format("  MPM, grid cell {:.4g} um\n", c.grid->cell_size * 1e6);
}

}  // namespace coldspray::cli
