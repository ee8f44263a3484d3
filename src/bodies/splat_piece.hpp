// The piece of a body that hangs together after an impact. A fast impact's molten rim sheds drops
// that fly off across the grid (at 1000-1300 m/s a 22 um Al particle leaves 9-15 points 20-50 um
// beyond its splat, docs/validation/bond-strength.md); they are part of the body's points but not
// of its splat, so measures of the splat's extent (the pull-off's grip, the flattening ratio)
// take only the piece holding most of the body's mass.
#pragma once

#include <cstddef>
#include <vector>

#include "bodies/bodies.hpp"

namespace coldspray::bodies {

// Two points belong to one piece when a chain of the body's points joins them with each link
// shorter than kPieceLinkSpacings point spacings: three, within both solvers' reach (an MPM point
// shares grid nodes with every point within a cell, four spacings by default; a peridynamic point
// has bonds within its horizon, 3.015 spacings).
inline constexpr double kPieceLinkSpacings = 3.0;

// Flags (1) the body's points [begin, end) in its heaviest piece, indexed from body.begin; ties
// go to the piece holding the lowest index. Serial and in index order, so the same on any
// thread count.
std::vector<char> splat_piece(const Points& P, const BodyRange& body);

}  // namespace coldspray::bodies
