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

#include "bonding/bond_law.hpp"
#include "case/case.hpp"
#include "materials/material.hpp"
#include "mpm/bond_shadows.hpp"
#include "mpm/contact.hpp"
#include "mpm/grid.hpp"
#include "mpm/points.hpp"
#include "mpm/stencil.hpp"
#include "mpm/work_shares.hpp"

namespace coldspray::mpm {

// What a body's points carried off the grid when they left it (mpm/departures.hpp), summed over
// them in index order at the end of the step in which each left.
struct Departed {
  std::size_t points = 0;
  double mass = 0.0;                 // kg
  std::array<double, 3> momentum{};  // kg m/s
  double kinetic = 0.0;              // 1/2 m v^2, J
  double internal = 0.0;             // E V0, J
  double plastic_work = 0.0;         // J, part of internal
  double viscous_work = 0.0;         // J
  double contact_work = 0.0;         // J
  double absorbed = 0.0;             // work done on their dashpots, J (absorbing-face points)
};

struct BodyRange {
  std::string name;
  std::size_t begin = 0;  // the body's points are [begin, end)
  std::size_t end = 0;
  materials::Material material;
  double spacing = 0.0;
  std::array<double, 3> initial_velocity{};  // m/s
  double initial_diameter = 0.0;             // lateral extent at t = 0, m
  // Where the body was cut by a symmetry plane normal to x or y (in r-z, x = r is cut at the
  // axis r = 0): the whole body is the modelled part and its mirror image, so its centre lies on
  // the plane and its areas are twice the modelled part's.
  std::array<std::optional<double>, 2> mirror_plane{};
  Departed departed{};  // the body's points that have left the grid
};

// A point on an absorbing face: Lysmer-Kuhlemeyer dashpots (thesis §3.5.5, eqs 3.45-3.46) give
// it the force -damping[a] * v_a along each axis a.
struct AbsorbingPoint {
  std::size_t point = 0;
  std::array<double, 3> damping{};  // N s/m
  double absorbed = 0.0;            // work done on the dashpots so far, J
};

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

// A fault found during a step: the lowest point index at fault, so the report is the same
// whatever the threads.
struct Fault {
  std::size_t point = std::numeric_limits<std::size_t>::max();
  std::string cause;
};

struct State {
  case_file::Geometry geometry = case_file::Geometry::ThreeD;
  case_file::ShapeFunction shape_function = case_file::ShapeFunction::Gimp;
  case_file::ArtificialViscosity viscosity;

  GridLayout layout;
  GridFields grid;
  std::vector<std::uint8_t> constraint;    // NodeConstraint bits per node
  std::vector<std::uint8_t> near_contact;  // per node: a stencil based there reaches contact

  Points points;
  std::vector<BodyRange> bodies;
  std::vector<AbsorbingPoint> absorbing;
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
  case_file::ImpactMetrics impact_metrics;

  double time = 0.0;
  double dt = 0.0;
  long step = 0;
  double max_signal_speed = 0.0;  // max over points of c + |v| after the last stress update
  double mass_floor = 0.0;        // nodes lighter than this carry no velocity, kg
  // solver.heat_conduction, and the largest thermal diffusivity k / (rho C_p) of the bodies, m^2/s
  // (the conduction's time-step limit, mpm/stepper.hpp).
  bool heat_conduction = false;
  double max_diffusivity = 0.0;
  Fault fault;
  std::size_t departing = 0;  // points that left the grid in this step (mpm/departures.hpp)
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
