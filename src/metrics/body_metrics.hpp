// Per-body measures for summaries and histories.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bodies/bodies.hpp"
#include "metrics/impact_metrics.hpp"
#include "metrics/verdict.hpp"

namespace coldspray::metrics {

struct BodyMetrics {
  std::string name;
  double mass = 0.0;                   // kg (the ring masses summed, in r-z), on the grid
  std::array<double, 3> velocity{};    // mass-averaged, m/s
  std::array<double, 3> centroid{};    // mass-averaged, m (x = r in r-z)
  std::array<double, 3> extent_min{};  // m
  std::array<double, 3> extent_max{};  // m
  double max_eqps = 0.0;
  double mean_eqps = 0.0;                 // mass-averaged
  double max_temperature = 0.0;           // K
  std::array<double, 3> contact_force{};  // from all other bodies over the last step, N
  ImpactMeasures impact;
  bodies::Departed departed;  // the points that have left the grid (the rest are of those on it)
  // For a body that moved in z at t = 0, at the end of a run: the verdict on its last window
  // (run/verdict_series.hpp); body_metrics leaves it empty.
  std::optional<Verdict> verdict;
};

// In index order: independent of the thread count. `extent`: whether the splats' extent (the
// flattening ratio) is measured, for a summary, or skipped, for a history row.
std::vector<BodyMetrics> body_metrics(const bodies::Bodies& s, SplatExtent extent);

}  // namespace coldspray::metrics
