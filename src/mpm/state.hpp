// Everything an MPM run carries from step to step. Built once by setup (mpm/setup.hpp); the
// step (mpm/stepper.hpp) only reads and writes it, allocating nothing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bodies/bodies.hpp"
#include "bonding/bond_law.hpp"
#include "case/case.hpp"
#include "materials/material.hpp"
#include "mpm/bond_shadows.hpp"
#include "mpm/contact.hpp"
#include "mpm/grid.hpp"
#include "mpm/stencil.hpp"
#include "mpm/work_shares.hpp"

namespace coldspray::mpm {

using bodies::AbsorbingPoint;
using bodies::BodyRange;
using bodies::Departed;
using bodies::Fault;
using bodies::Points;

// Bits of State::constraint: the velocity components held at zero at a node.
enum NodeConstraint : std::uint8_t { kHoldX = 1, kHoldY = 2, kHoldZ = 4 };

// Points binned into blocks of kBlockCells cell layers in y and in z, across the whole grid in x.
// A point's support reaches one node below its cell and two above, so blocks two apart along y
// or z never share a node, and the blocks of one colour (the parities of their y and z indices)
// can all scatter to the grid at once; the four colours go in turn. The order is fixed, whatever
// the threads. (z slabs alone leave a flat substrate in a few heavy slabs that two threads
// cannot share evenly. Strips along y rather than x because points are seeded with x fastest:
// a block keeps whole rows of points contiguous in memory, where x strips cut them into runs of
// a few points and made the scatter three times slower.)
struct Blocks {
  static constexpr int kBlockCells = 3;
  static constexpr int kColours = 4;
  // The points are counted in this many fixed chunks, in parallel: the order does not depend on
  // the threads.
  static constexpr int kSortChunks = 16;
  std::size_t row = 0;                  // blocks of one colour along y
  std::size_t per_colour = 0;           // blocks of each colour
  std::vector<std::uint32_t> order;     // point indices, by block, ascending within a block
  std::vector<std::size_t> begin;       // block b is order[begin[b] .. begin[b+1]), by colour
  std::vector<std::uint32_t> block_of;  // scratch: each point's block
  std::vector<std::size_t> cursor;      // scratch: kSortChunks x blocks counts, then offsets
};

// The bodies (bodies/bodies.hpp: points, ranges, boundary points, clock) and the grid that moves
// them.
struct State : bodies::Bodies {
  case_file::ShapeFunction shape_function = case_file::ShapeFunction::Gimp;
  case_file::ArtificialViscosity viscosity;

  GridLayout layout;
  GridFields grid;
  std::vector<std::uint8_t> constraint;    // NodeConstraint bits per node
  std::vector<std::uint8_t> near_contact;  // per node: a stencil based there reaches contact

  std::array<std::vector<double>, 3> external_force;  // per point, N (dashpots)
  Blocks blocks;
  WorkShares stress_shares;  // the threads' shares of the stress update
  // Each point's stencil at the step's positions: evaluated once, by the particle-to-grid
  // mapping, and read by every later phase of the step, as the points move only at its end
  // (step 11). One vector per shape function and geometry; setup sizes the run's own.
  std::tuple<std::vector<Stencil<LinearShape, false>>, std::vector<Stencil<LinearShape, true>>,
             std::vector<Stencil<GimpShape, false>>, std::vector<Stencil<GimpShape, true>>>
      stencils;

  ContactNodes contact;
  ContactRule contact_rule;
  ContactResult contact_result;  // of the last step
  bonding::BondLaw bond_law;     // D_bond evolution (thesis Chapter 4)
  // Other runs' bond laws followed alongside (studies' bond families); while any are, this run's
  // own D_bond stays zero.
  BondShadows bond_shadows;

  double mass_floor = 0.0;  // nodes lighter than this carry no velocity, kg
  // solver.heat_conduction, and the largest thermal diffusivity k / (rho C_p) of the bodies, m^2/s
  // (the conduction's time-step limit, mpm/stepper.hpp).
  bool heat_conduction = false;
  double max_diffusivity = 0.0;
  std::size_t departing = 0;  // points that left the grid in this step (mpm/departures.hpp)
  // The time step that Points::displacement spans (the last step's; 0 before the first): the
  // absorbing dashpots read the velocity from it (mpm/boundaries.hpp).
  double displacement_dt = 0.0;
};

// Calls f.template operator()<Shape, Axisymmetric>() for the run's shape function and geometry:
// where the solver's templates are chosen.
template <class F>
decltype(auto) with_discretisation(const State& s, F&& f) {
  const bool axi = s.geometry == case_file::Geometry::Axisymmetric;
  const bool gimp = s.shape_function == case_file::ShapeFunction::Gimp;
  if (gimp && axi) return f.template operator()<GimpShape, true>();
  if (gimp) return f.template operator()<GimpShape, false>();
  if (axi) return f.template operator()<LinearShape, true>();
  return f.template operator()<LinearShape, false>();
}

}  // namespace coldspray::mpm
