#include "cli/case_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <ostream>
#include <utility>

#include "case/size_estimate.hpp"
#include "geometry/shape.hpp"
#include "run/solver.hpp"

namespace coldspray::cli {

namespace {

// A length unit, for printing the case in the scale it was written in.
struct LengthUnit {
  const char* symbol;
  double metres;
};

// The unit in which the largest body measures from 1 to 1000: um for a particle, mm for a
// Taylor bar, so that check's summary reads as the case file does.
LengthUnit unit_of_scale(const case_file::Case& c) {
  double largest = 0.0;
  for (const auto& b : c.bodies) {
    const geometry::Bounds box = geometry::bounding_box(b.shape);
    largest = std::max(largest, (box.max - box.min).maxCoeff());
  }
  static constexpr std::array<LengthUnit, 4> kUnits{
      {{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}}};
  for (const LengthUnit& u : kUnits)
    if (largest >= u.metres) return u;
  return kUnits.back();
}

std::string describe(const geometry::Shape& shape, const LengthUnit& u) {
  auto length = [&u](double metres) {
    return fmt::format("{:.4g} {}", metres / u.metres, u.symbol);
  };
  if (const auto* s = std::get_if<geometry::Sphere>(&shape))
    return fmt::format("sphere r = {}", length(s->radius));
  if (const auto* c = std::get_if<geometry::Cylinder>(&shape))
    return fmt::format("cylinder r = {}, h = {}", length(c->radius), length(c->height));
  const auto& b = std::get<geometry::Box>(shape);
  const Eigen::Vector3d size = (b.max - b.min) / u.metres;
  return fmt::format("box {:.4g} x {:.4g} x {:.4g} {}", size.x(), size.y(), size.z(), u.symbol);
}

}  // namespace

void print_case_summary(const case_file::Case& c, std::ostream& out) {
  const bool axisymmetric = c.solver.geometry == case_file::Geometry::Axisymmetric;
  const LengthUnit u = unit_of_scale(c);
  out << fmt::format("case '{}': {}, {} bodies, end time {:.4g} ns\n", c.name,
                     axisymmetric ? "axisymmetric" : "3D", c.bodies.size(),
                     c.solver.end_time * 1e9);
  // A run whose moving body is undecided at the end time goes on (run/step_rule.hpp), which a
  // short end time would not lead one to expect (docs/bonding.md, "Verdict").
  const bool has_verdict = std::any_of(c.bodies.begin(), c.bodies.end(),
                                       [](const auto& b) { return b.velocity.z() != 0.0; });
  if (has_verdict && c.metrics.verdict_extensions > 0)
    out << fmt::format(
        "  verdict over the last {:.4g} ns; while a body is undecided the run goes on by up to "
        "{} x {:.4g} ns (metrics.verdict_extensions)\n",
        c.metrics.verdict_window * 1e9, c.metrics.verdict_extensions,
        c.metrics.verdict_window * 1e9);
  for (const auto& b : c.bodies) {
    // A coarsened body has fewer: the estimate counts the uniform lattice.
    out << fmt::format(
        "  body '{}': {}, material {}, spacing {:.4g} {}, {}~{:.3g} points{}\n", b.name,
        describe(b.shape, u), b.material, b.spacing / u.metres, u.symbol,
        b.coarsening ? "at most " : "", case_file::estimated_points(c, b),
        b.coarsening ? fmt::format(" (coarsened, {} levels)", b.coarsening->levels) : "");
  }
  out << run::with_solver(c.solver.method, [&](auto solver) {
    return describe_discretisation(solver, c, u.metres, u.symbol);
  });
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
