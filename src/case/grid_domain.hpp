// Where the MPM grid lies: the domain it covers before its faces are put on whole cells. The
// set-up (mpm/setup.cpp) and the case's size estimate (case/size_estimate.hpp) both place it so.
#pragma once

#include <utility>

#include "case/case.hpp"

namespace coldspray::case_file {

// The margin added around the bodies when grid.min/max are not given: half the bodies' extent
// along each axis (at least 4 cells), so that rebounding and jetted material stays on the grid
// through a typical impact. A point that still leaves the domain leaves the run
// (mpm/departures.hpp).
inline constexpr double kGridMarginFraction = 0.5;
inline constexpr int kGridMarginMinCells = 4;

// grid.min..grid.max, or the bodies' bounds lo..hi plus the margin; in r-z from the axis.
std::pair<Vec3, Vec3> grid_domain(const Case& c, Vec3 lo, Vec3 hi);

}  // namespace coldspray::case_file
