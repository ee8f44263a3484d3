// Points that leave the grid leave the computation (issue 22): a jetted fragment flying off the
// grid does not end the run. At the end of the step in which a point moved out of the domain, it
// is booked into its body's ledger (BodyRange::departed: mass, momentum, energies) and removed
// from the points and from everything that indexes them, the others keeping their order. The
// energy budget and the metrics count the ledger (docs/mpm.md, "Points that leave the grid").
// A body whose bulk leaves still stops the run: that is no jet, the grid is too small.
#pragma once

#include <cstddef>

#include "mpm/state.hpp"

namespace coldspray::mpm {

// Whether point p lies outside the domain, the nodes inside the ghost layer (mpm/setup.cpp),
// along an axis the grid spans: its support would reach past the ghost nodes.
inline bool outside_domain(const GridLayout& L, const Points& P, std::size_t p) {
  for (int d = 0; d < 3; ++d) {
    if (L.nodes[d] == 1) continue;
    const double lo = L.origin[d] + L.h, hi = L.extent(d) - L.h;
    if (P.position[d][p] < lo || P.position[d][p] > hi) return true;
  }
  return false;
}

// A body more than this fraction of whose mass has left the grid stops the run. Jets take a few
// percent of a particle's mass (6 % for 14 um Al at 810 m/s, docs/impact.md); when half of it has
// gone, the body itself has flown off (a rebound or a fall through a grid too small for it), and
// its metrics would describe what little is left.
inline constexpr double kDepartedBulkFraction = 0.5;

// After a step in which s.departing points moved out of the domain: books each into its body's
// ledger and removes it. A rare event: one pass over every per-point array, without reallocation
// (the lists of the departing points, their bond-shadow columns and their bodies' masses are
// allocated). Throws RunFault naming the body and the fraction, with the state as the step left
// it, when a body's departed mass would exceed kDepartedBulkFraction of its mass.
void remove_departed_points(State& s);

// Sizes what the step rebuilds for the points (stencils, blocks, external forces) to the
// points' count: after points left, or when a restarted run reads fewer points than its setup
// seeded (run/checkpoints.hpp).
void fit_scratch_to_points(State& s);

}  // namespace coldspray::mpm
