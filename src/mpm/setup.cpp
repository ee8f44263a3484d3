#include "mpm/setup.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "bodies/grip.hpp"
#include "bodies/seed_bodies.hpp"
#include "case/grid_domain.hpp"
#include "case/located_error.hpp"
#include "core/error.hpp"
#include "geometry/seeding.hpp"
#include "mpm/contact.hpp"
#include "mpm/phases.hpp"
#include "mpm/stencil.hpp"

namespace coldspray::mpm {

namespace {

using case_file::Vec3;

// Places the grid. The domain is grid.min..grid.max, or the bodies' bounds plus a margin, with
// its faces on multiples of the cell size so that the points' lattice (anchored at 0) lines up
// with the cells. One layer of ghost nodes lies outside every face: a GIMP support reaches a
// node beyond the point's cell, and bodies may fill the domain up to a fixed or roller face.
// In r-z the domain starts at the axis r = 0.
GridLayout place_grid(const case_file::Case& c, const std::vector<bodies::SeededBody>& seeded) {
  const double h = c.grid->cell_size;
  const bool axi = c.solver.geometry == case_file::Geometry::Axisymmetric;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 hi = -lo;
  for (const bodies::SeededBody& s : seeded) {
    lo = lo.cwiseMin(s.min);
    hi = hi.cwiseMax(s.max);
  }
  std::tie(lo, hi) = case_file::grid_domain(c, lo, hi);
  GridLayout g;
  g.h = h;
  g.axisymmetric = axi;
  for (int d = 0; d < 3; ++d) {
    const double first = std::floor(lo[d] / h + 1e-9) * h;
    const double last = std::ceil(hi[d] / h - 1e-9) * h;
    g.origin[d] = first - h;
    g.nodes[d] = static_cast<int>(std::lround((last - first) / h)) + 3;
  }
  if (axi) {
    g.origin[1] = 0.0;
    g.nodes[1] = 1;
  }
  return g;
}

void check_inside_grid(const case_file::Case& c, const std::vector<bodies::SeededBody>& seeded,
                       const GridLayout& g) {
  for (std::size_t b = 0; b < seeded.size(); ++b)
    for (int d = 0; d < 3; ++d) {
      if (g.nodes[d] == 1) continue;
      const double tolerance = 1e-9 * g.h;
      const bool below = seeded[b].min[d] < g.origin[d] + g.h - tolerance;
      if (below || seeded[b].max[d] > g.extent(d) - g.h + tolerance) {
        case_file::fail_at(c, below ? "grid.min" : "grid.max",
                           fmt::format("body '{}' reaches outside the grid along {}: enlarge "
                                       "grid.min/grid.max",
                                       c.bodies[b].name, "xyz"[d]));
      }
    }
}

// A body may cross a fixed or roller face of the grid: such a face is a symmetry plane (a
// quarter of a Taylor bar, half of a plate) and the body is cut there.
std::vector<bodies::CutPlane> symmetry_faces(const case_file::Case& c, const GridLayout& g) {
  std::vector<bodies::CutPlane> planes;
  for (const auto& [face, condition] : c.grid->faces) {
    if (condition == case_file::FaceCondition::Free) continue;
    const int axis = static_cast<int>(face) / 2;
    if (g.nodes[axis] == 1) continue;
    const bool at_max = static_cast<int>(face) % 2 == 1;
    planes.push_back({axis, at_max ? g.extent(axis) - g.h : g.origin[axis] + g.h, !at_max});
  }
  return planes;
}

// The holds of the grid faces, on the face's node layer and the ghost layer beyond it, and in
// r-z the axis: no radial velocity at r <= 0.
void constrain_grid_faces(const case_file::Case& c, State& s) {
  const GridLayout& L = s.layout;
  for (const auto& [face, condition] : c.grid->faces) {
    if (condition == case_file::FaceCondition::Free) continue;
    const int axis = static_cast<int>(face) / 2;
    const bool at_max = static_cast<int>(face) % 2 == 1;
    if (L.nodes[axis] == 1) continue;
    const int face_layer = at_max ? L.nodes[axis] - 2 : 1;
    const int ghost_layer = at_max ? L.nodes[axis] - 1 : 0;
    const std::uint8_t held = condition == case_file::FaceCondition::Fixed
                                  ? (kHoldX | kHoldY | kHoldZ)
                                  : static_cast<std::uint8_t>(1u << axis);
    for (int k = 0; k < L.nodes[2]; ++k)
      for (int j = 0; j < L.nodes[1]; ++j)
        for (int i = 0; i < L.nodes[0]; ++i) {
          const int ijk[3] = {i, j, k};
          if (ijk[axis] == face_layer || ijk[axis] == ghost_layer)
            s.constraint[L.index(i, j, k)] |= held;
        }
  }
  if (L.axisymmetric)
    for (int k = 0; k < L.nodes[2]; ++k)
      for (int i = 0; i <= 1; ++i) s.constraint[L.index(i, 0, k)] |= kHoldX;
}

// Fixed faces hold every node the face's points reach.
template <class Shape, bool Axisymmetric>
void hold_nodes_of_point(State& s, std::size_t p) {
  Stencil<Shape, Axisymmetric> st;
  const Points& P = s.points;
  st.evaluate(s.layout, P, p);
  st.for_each(s.layout, [&](std::size_t n, double w, double, double, double) {
    if (w > 0.0) s.constraint[n] = kHoldX | kHoldY | kHoldZ;
  });
}

void hold_fixed_point(State& s, std::size_t p) {
  const bool axi = s.layout.axisymmetric;
  if (s.shape_function == case_file::ShapeFunction::Gimp)
    axi ? hold_nodes_of_point<GimpShape, true>(s, p) : hold_nodes_of_point<GimpShape, false>(s, p);
  else
    axi ? hold_nodes_of_point<LinearShape, true>(s, p)
        : hold_nodes_of_point<LinearShape, false>(s, p);
}

// The bodies whose points reach each node at t = 0, counted once each: the points of a body are
// one range, so a node's last counted body tells whether this one is new to it.
template <class Shape, bool Axisymmetric>
std::vector<int> bodies_per_node(const State& s) {
  std::vector<int> count(s.layout.node_count(), 0), last(s.layout.node_count(), -1);
  Stencil<Shape, Axisymmetric> st;
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (std::size_t p = s.bodies[b].begin; p < s.bodies[b].end; ++p) {
      st.evaluate(s.layout, s.points, p);
      st.for_each(s.layout, [&](std::size_t n, double w, double, double, double) {
        if (w <= 0.0 || last[n] == static_cast<int>(b)) return;
        last[n] = static_cast<int>(b);
        ++count[n];
      });
    }
  return count;
}

// um, without the rounding noise of the grid's origin (-2e-22 m for 0).
double micrometres(double metres) { return std::round(metres * 1e12) / 1e6 + 0.0; }

// The contact keeps at most kMaxBodiesPerNode bodies at a node (mpm/contact.hpp); bodies that
// start with more at one node are bad input rather than a fault of the run's first step.
void check_bodies_per_node(const case_file::Case& c, const State& s) {
  const std::vector<int> count = with_discretisation(
      s, [&]<class Shape, bool Axisymmetric>() { return bodies_per_node<Shape, Axisymmetric>(s); });
  const auto most = std::max_element(count.begin(), count.end());
  if (most == count.end() || *most <= kMaxBodiesPerNode) return;
  const std::size_t n = static_cast<std::size_t>(most - count.begin());
  const GridLayout& L = s.layout;
  const std::size_t i = n % L.nodes[0], j = n / L.nodes[0] % L.nodes[1],
                    k = n / L.nodes[0] / L.nodes[1];
  case_file::fail_at(
      c, "bodies",
      fmt::format("{} bodies reach the grid node at ({:.4g}, {:.4g}, {:.4g}) um at t = 0; the "
                  "contact holds at most {} bodies at a node (docs/mpm.md): move the bodies "
                  "apart by two cells",
                  *most, micrometres(L.coordinate(0, static_cast<int>(i))),
                  micrometres(L.coordinate(1, static_cast<int>(j))),
                  micrometres(L.coordinate(2, static_cast<int>(k))), kMaxBodiesPerNode));
}

}  // namespace

State build_state(const case_file::Case& c) {
  State s;
  s.shape_function = c.solver.shape_function;
  s.viscosity = c.solver.artificial_viscosity;

  std::vector<bodies::SeededBody> seeded = bodies::seed_bodies(c);
  s.layout = place_grid(c, seeded);
  bodies::cut_at_planes(c, symmetry_faces(c, s.layout), "the grid's fixed and roller faces",
                        seeded);
  check_inside_grid(c, seeded, s.layout);
  bodies::lay_out_bodies(c, seeded, s);
  s.discretisation = {"mpm", "cell_size", c.grid->cell_size, std::nullopt};
  const std::size_t total = s.points.size();
  const Points& P = s.points;

  s.grid.resize(s.layout.node_count());
  s.constraint.assign(s.layout.node_count(), 0);
  s.near_contact.assign(s.layout.node_count(), 0);
  constrain_grid_faces(c, s);
  for (auto& f : s.external_force) f.assign(total, 0.0);
  bodies::prepare_grip(s, c.grip);
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const std::uint8_t fixed = bodies::faces_bits(c.bodies[b].fixed);
    for (std::size_t i = 0; i < seeded[b].points.outside.size(); ++i)
      if (seeded[b].points.outside[i] & fixed) hold_fixed_point(s, s.bodies[b].begin + i);
  }

  check_bodies_per_node(c, s);
  with_discretisation(s, [&]<class Shape, bool Axisymmetric>() {
    std::get<std::vector<Stencil<Shape, Axisymmetric>>>(s.stencils).resize(total);
  });
  // Blocks cover the nodes (and so every point inside the ghost layer) along y and z.
  Blocks& blocks = s.blocks;
  const int strips = s.layout.nodes[1] / Blocks::kBlockCells + 2;
  const int slabs = s.layout.nodes[2] / Blocks::kBlockCells + 2;
  blocks.row = static_cast<std::size_t>(strips + 1) / 2;
  blocks.per_colour = blocks.row * static_cast<std::size_t>((slabs + 1) / 2);
  blocks.order.resize(total);
  blocks.block_of.resize(total);
  blocks.begin.resize(Blocks::kColours * blocks.per_colour + 1);
  blocks.cursor.resize(Blocks::kSortChunks * (blocks.begin.size() - 1));
  // Sized here so that steps allocate only if the thread count changes between them.
  s.stress_shares.prepare(omp_get_max_threads(), stress_batch_count(s));

  s.contact_rule.normal = c.contact.mpm.normal;
  s.contact_rule.other_pairs = c.contact.mpm.other_pairs_normal;
  s.contact_rule.friction = c.contact.mpm.friction;
  s.contact_rule.gap_check = c.contact.mpm.gap_check;
  s.bond_law = bonding::BondLaw::from_case(c.bonding, c.grid->cell_size);
  s.bonding = s.bond_law.enabled();
  s.contact_rule.bonding = s.bonding;
  s.contact_rule.activation = s.bond_law.critical_penetration > 0.0;
  s.contact_rule.may_bond.assign(s.bodies.size() * s.bodies.size(), 1);
  s.contact_rule.nodal_average = c.bonding.nodal_average;
  s.contact_rule.debond = bonding::CohesiveLaw::from_case(c.bonding);
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    s.contact_rule.reference_density.push_back(s.bodies[b].material.density);
    if (c.contact.mpm.normal == case_file::ContactNormal::Body &&
        c.bodies[b].name == c.contact.mpm.normal_body)
      s.contact_rule.normal_body = static_cast<int>(b);
  }
  s.contact_result.gradient_weight.assign(c.bodies.size() * c.bodies.size(), 0.0);
  s.contact_result.master.assign(c.bodies.size() * c.bodies.size(), 0);

  s.mass_floor = 1e-10 * *std::min_element(P.mass.begin(), P.mass.end());
  s.contact_rule.mass_floor = s.mass_floor;
  s.heat_conduction = c.solver.heat_conduction;
  if (s.heat_conduction) {
    s.grid.heat.resize(s.layout.node_count());
    for (const BodyRange& b : s.bodies)
      s.max_diffusivity =
          std::max(s.max_diffusivity, b.material.thermal.conductivity /
                                          (b.material.density * b.material.thermal.specific_heat));
  }
  return s;
}

}  // namespace coldspray::mpm
