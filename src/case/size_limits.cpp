#include "case/size_limits.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "case/size_estimate.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

// Nodes along one axis, at most: GridLayout counts them in an int.
constexpr double kMaxNodesPerAxis = 1 << 30;

SizeCap cap_of(const std::optional<double>& given, const char* key, double bytes,
               const char* item) {
  if (given) return {*given, fmt::format("limits.{} = {:.3g}", key, *given)};
  const double memory = available_memory_bytes();
  const double value = std::floor(memory / bytes);
  return {value, fmt::format("limits.{}, by default {:.3g}: the {:.3g} GB of memory available at "
                             "{:.0f} bytes per {}",
                             key, value, memory * 1e-9, bytes, item)};
}

// The key that sizes a body's shape: a sphere's or cylinder's radius, a box's max corner.
std::vector<std::string> size_key(const Body& b) {
  return {"bodies", b.name, "shape",
          std::holds_alternative<geometry::Box>(b.shape) ? "max" : "radius"};
}

void check_points(const Document& doc, const Case& c) {
  const SizeCap cap = point_cap(c);
  double total = 0.0, most = -1.0;
  std::size_t largest = 0;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const double n = estimated_points(c, c.bodies[i]);
    total += n;
    if (!(n <= most)) {
      most = n;
      largest = i;
    }
  }
  if (total <= cap.value) return;
  const Body& b = c.bodies[largest];
  fail_at(
      doc, size_key(b),
      fmt::format("the bodies would have about {:.3g} points (body '{}' about {:.3g}, its shape "
                  "at spacing {:.4g} m), more than {}: coarsen the spacing, make the body "
                  "smaller or raise limits.max_points",
                  total, b.name, most, b.spacing, cap.source));
}

void check_grid(const Document& doc, const Case& c) {
  if (c.solver.method != Method::Mpm) return;
  const std::array<double, 3> nodes = estimated_grid_nodes(c);
  const double total = nodes[0] * nodes[1] * nodes[2];
  const SizeCap cap = cap_of(c.limits.max_grid_nodes, "max_grid_nodes", kGridBytesPerNode, "node");
  const bool per_axis = !(std::max({nodes[0], nodes[1], nodes[2]}) <= kMaxNodesPerAxis);
  if (total <= cap.value && !per_axis) return;
  fail_at(
      doc, {"grid", "cell_size"},
      fmt::format("the grid would have about {:.3g} nodes ({:.3g} x {:.3g} x {:.3g} at cell size "
                  "{:.4g} m), more than {}: a coarser cell, a smaller domain (grid.min/max, or "
                  "smaller bodies) or a larger limits.max_grid_nodes",
                  total, nodes[0], nodes[1], nodes[2], c.grid->cell_size,
                  per_axis ? fmt::format("{:.3g} along an axis", kMaxNodesPerAxis) : cap.source));
}

void check_steps(const Document& doc, const Case& c, const FirstStep& first) {
  const double steps = c.solver.end_time / first.dt;
  if (steps <= c.limits.max_steps) return;
  const Body& b = c.bodies[first.body];
  fail_at(doc, {"solver", "end_time"},
          fmt::format("the run would take about {:.3g} steps (end time {:.4g} s over a first step "
                      "of {:.3g} s, set by body '{}': material {}'s wave speed plus its speed, "
                      "{:.3g} m/s), more than limits.max_steps = {:.3g}: check the material's "
                      "density and moduli, shorten the end time or raise limits.max_steps",
                      steps, c.solver.end_time, first.dt, b.name, b.material, first.signal_speed,
                      c.limits.max_steps));
}

// An interval shorter than a step outputs at every step (as a valid case may ask), but one far
// shorter stalled the run: the output schedule steps through every interval a step crosses, and
// below the rounding of the time it never gets past one. Refused below kMinIntervalSteps of the
// first step: the schedule's work per output then stays under a thousand additions.
constexpr double kMinIntervalSteps = 1e-3;

void check_interval(const Document& doc, const FirstStep& first, double interval, const char* key,
                    const char* zero_means) {
  if (interval <= 0.0 || interval >= kMinIntervalSteps * first.dt) return;
  fail_at(doc, {"output", key},
          fmt::format("{:.3g} s is less than a thousandth of the first time step ({:.3g} s), "
                      "and outputs come at most once a step: give 0 ({}) or at least {:.3g} s",
                      interval, first.dt, zero_means, kMinIntervalSteps * first.dt));
}

}  // namespace

SizeCap point_cap(const Case& c) {
  const bool pd = c.solver.method == Method::Peridynamics;
  const double bonds =
      pd ? 4.0 / 3.0 * std::numbers::pi * std::pow(c.peridynamics->horizon_factor + 0.5, 3) : 0.0;
  const double bytes = pd ? kPdBytesPerPoint + kPdBytesPerBond * bonds : kMpmBytesPerPoint;
  return cap_of(c.limits.max_points, "max_points", bytes, "point");
}

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    if (line.starts_with("MemAvailable:")) return std::stod(line.substr(13)) * 1024.0;  // kB
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0) return static_cast<double>(pages) * page_size;
  return 4.0 * 1024 * 1024 * 1024;
}

void check_size_limits(const Document& doc, const Case& c) {
  check_points(doc, c);
  check_grid(doc, c);
  const FirstStep first = first_time_step(c);
  check_steps(doc, c, first);
  check_interval(doc, first, c.output.snapshot_interval, "snapshot_interval",
                 "the first and last only");
  check_interval(doc, first, c.output.history_interval, "history_interval", "every step");
}

}  // namespace coldspray::case_file
