#include "cli/case_summary.hpp"

#include <fmt/format.h>

#include <array>
#include <ostream>
#include <utility>

#include "case/size_estimate.hpp"

namespace coldspray::cli {

namespace {

std::string describe(const case_file::Shape& shape) {
  if (const auto* s = std::get_if<case_file::Sphere>(&shape))
    return fmt::format("sphere r = {:.4g} um", s->radius * 1e6);
  if (const auto* c = std::get_if<case_file::Cylinder>(&shape))
    return fmt::format("cylinder r = {:.4g} um, h = {:.4g} um", c->radius * 1e6, c->height * 1e6);
  const auto& b = std::get<case_file::Box>(shape);
  const Eigen::Vector3d size = b.max - b.min;
  return fmt::format("box {:.4g} x {:.4g} x {:.4g} um", size.x() * 1e6, size.y() * 1e6,
                     size.z() * 1e6);
}

}  // namespace

void print_case_summary(const case_file::Case& c, std::ostream& out) {
  const bool axisymmetric = c.solver.geometry == case_file::Geometry::Axisymmetric;
  out << fmt::format("case '{}': {}, {} bodies, end time {:.4g} ns\n", c.name,
                     axisymmetric ? "axisymmetric" : "3D", c.bodies.size(),
                     c.solver.end_time * 1e9);
  for (const auto& b : c.bodies) {
    out << fmt::format("  body '{}': {}, material {}, spacing {:.4g} um, ~{:.3g} points\n", b.name,
                       describe(b.shape), b.material, b.spacing * 1e6,
                       case_file::estimated_points(c, b));
  }
  if (c.solver.method == case_file::Method::Peridynamics)
    out << fmt::format("  peridynamics, horizon {:.4g} x spacing\n",
                       c.peridynamics->horizon_factor);
  else {
    const std::array<double, 3> nodes = case_file::estimated_grid_nodes(c);
    out << fmt::format("  MPM, grid cell {:.4g} um, ~{:.3g} nodes\n", c.grid->cell_size * 1e6,
                       nodes[0] * nodes[1] * nodes[2]);
  }
  const case_file::FirstStep first = case_file::first_time_step(c);
  out << fmt::format("  first time step {:.3g} ns, ~{:.3g} steps\n", first.dt * 1e9,
                     c.solver.end_time / first.dt);
  // Outputs come at most once a step: an interval below it is honoured at every step.
  for (const auto& [key, interval] : {std::pair{"history_interval", c.output.history_interval},
                                      std::pair{"snapshot_interval", c.output.snapshot_interval}})
    if (interval > 0.0 && interval < first.dt)
      out << fmt::format(
          "  warning: output.{} ({:.3g} ns) is shorter than the first time step: an output "
          "every step\n",
          key, interval * 1e9);
}

}  // namespace coldspray::cli
