// How large a case will be, from its keys alone, before anything is allocated: the points each
// body seeds, the MPM grid's nodes and the first time step. `check` prints them and the size
// limits (case/size_limits.hpp) hold them against their caps.
#pragma once

#include <array>
#include <cstddef>

#include "case/case.hpp"

namespace coldspray::case_file {

// The lattice sites in the body's shape: its volume / spacing^3 in 3D, times the part of its
// bounding box that the symmetry planes (peridynamics) or the fixed and roller grid faces (MPM)
// keep; its r-z half-section (x >= 0) / spacing^2 in axisymmetric geometry. In double: an absurd
// body gives a huge number, not an overflow. A coarsened body (Body::coarsening) has fewer: this
// counts its uniform lattice, an upper bound.
double estimated_points(const Case& c, const Body& b);

// The lattice sites in a whole shape in 3D, none cut away: its volume / spacing^3. For a
// generator that sizes its case before writing it (`coldspray deposit`).
double lattice_points(const geometry::Shape& shape, double spacing);

// The MPM grid's nodes along x, y, z, placed as mpm/setup.cpp places them (grid.min/max, or the
// bodies' bounding boxes plus the margin, on multiples of the cell size, a ghost layer beyond).
std::array<double, 3> estimated_grid_nodes(const Case& c);

// The time step at t = 0, as run/step_rule.hpp takes it: cfl (or dt_scale) times the cell size
// (MPM) or the finest spacing (peridynamics) over the fastest signal, a body's wave speed plus
// its speed; with heat conduction, at most the conduction bound.
struct FirstStep {
  double dt = 0.0;            // s
  std::size_t body = 0;       // the body whose signal speed sets it
  double signal_speed = 0.0;  // m/s
};
FirstStep first_time_step(const Case& c);

}  // namespace coldspray::case_file
