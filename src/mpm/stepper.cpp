#include "mpm/stepper.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "materials/conduction_step.hpp"
#include "mpm/boundaries.hpp"
#include "mpm/departures.hpp"
#include "mpm/heat_conduction.hpp"
#include "mpm/phases.hpp"

namespace coldspray::mpm {

namespace {

// Bins the points into blocks (State::Blocks), stable in the point index: the order every
// point-to-grid phase scatters in, and so the order of every nodal sum. A counting sort over fixed
// chunks of the points: each chunk counts its points per block, the chunks' shares of each block
// follow one another in chunk order, and each chunk then places its points in index order.
void bin_points_into_blocks(State& s) {
  Blocks& B = s.blocks;
  const Points& P = s.points;
  const GridLayout& L = s.layout;
  const long n = static_cast<long>(P.size());
  const std::size_t blocks = B.begin.size() - 1;
  const double inv = 1.0 / (L.h * Blocks::kBlockCells);
  const bool flat = L.nodes[1] == 1;  // r-z: one layer of nodes in y
  auto block_of = [&](std::size_t p) {
    const auto z = static_cast<std::size_t>((P.position[2][p] - L.origin[2]) * inv);
    const auto y = flat ? 0 : static_cast<std::size_t>((P.position[1][p] - L.origin[1]) * inv);
    const std::size_t colour = (z % 2) * 2 + y % 2;
    return static_cast<std::uint32_t>(colour * B.per_colour + (z / 2) * B.row + y / 2);
  };
  auto chunk_begin = [&](long c) { return static_cast<std::size_t>(n * c / Blocks::kSortChunks); };
#pragma omp parallel for schedule(static)
  for (long c = 0; c < Blocks::kSortChunks; ++c) {
    std::size_t* count = &B.cursor[static_cast<std::size_t>(c) * blocks];
    std::fill_n(count, blocks, 0);
    for (std::size_t p = chunk_begin(c); p < chunk_begin(c + 1); ++p) {
      B.block_of[p] = block_of(p);
      ++count[B.block_of[p]];
    }
  }
  std::size_t offset = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    B.begin[b] = offset;
    for (std::size_t c = 0; c < Blocks::kSortChunks; ++c) {
      std::size_t& k = B.cursor[c * blocks + b];
      offset += std::exchange(k, offset);
    }
  }
  B.begin[blocks] = offset;
#pragma omp parallel for schedule(static)
  for (long c = 0; c < Blocks::kSortChunks; ++c) {
    std::size_t* cursor = &B.cursor[static_cast<std::size_t>(c) * blocks];
    for (std::size_t p = chunk_begin(c); p < chunk_begin(c + 1); ++p)
      B.order[cursor[B.block_of[p]]++] = static_cast<std::uint32_t>(p);
  }
}

// The nodes two or more bodies reach get a contact slot. The stencils that reach such a node are
// flagged by their lowest node (near_contact, phases.hpp), so the phases that work at contact
// nodes skip every other point, and the rest read the grid's velocities without looking up.
template <class Shape, bool Axisymmetric>
void find_contact_nodes(State& s) {
  constexpr int reach = Stencil<Shape, Axisymmetric>::S - 1;
  constexpr int reach_y = Stencil<Shape, Axisymmetric>::SY - 1;
  s.contact.clear();
  std::fill(s.near_contact.begin(), s.near_contact.end(), 0);
  const GridLayout& L = s.layout;
  for (std::size_t n = 0; n < L.node_count(); ++n) {
    if (s.grid.reached_by[n] != GridFields::kManyBodies) continue;
    s.grid.contact_slot[n] = s.contact.add(n);
    const int i = static_cast<int>(n % L.nodes[0]);
    const int j = static_cast<int>((n / L.nodes[0]) % L.nodes[1]);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(L.nodes[0]) * L.nodes[1]));
    for (int bk = std::max(k - reach, 0); bk <= k; ++bk)
      for (int bj = std::max(j - reach_y, 0); bj <= j; ++bj)
        for (int bi = std::max(i - reach, 0); bi <= i; ++bi)
          s.near_contact[L.index(bi, bj, bk)] = 1;
  }
}

// Step 3 (eq 3.28): p += f dt at every node, total and per body; then the essential boundary
// conditions, on momentum and force alike so constrained nodes neither move nor accelerate.
void integrate_grid_momentum(State& s) {
  GridFields& g = s.grid;
  const long nodes = static_cast<long>(s.layout.node_count());
  const double dt = s.dt;
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n)
    for (int d = 0; d < 3; ++d) g.sums[n].momentum[d] += g.sums[n].force[d] * dt;
  ContactNodes& c = s.contact;
  for (std::size_t slot = 0; slot < c.size(); ++slot)
    for (int e = 0; e < c.body_count(static_cast<std::int32_t>(slot)); ++e) {
      const std::size_t f = ContactNodes::flat(static_cast<std::int32_t>(slot), e);
      for (int d = 0; d < 3; ++d) c.momentum[d][f] += c.force[d][f] * dt;
    }
  apply_node_constraints(s, /*force_too=*/true);
}

}  // namespace

double stable_time_step(const State& s, double cfl) {
  const double mechanical = cfl * s.layout.h / s.max_signal_speed;
  if (!s.heat_conduction || s.max_diffusivity <= 0.0) return mechanical;
  return std::min(mechanical, materials::conduction_step_limit(s.layout.h, s.layout.axisymmetric,
                                                               s.max_diffusivity));
}

void activate_bonding(State& s) {
  if (!s.bonding) return;
  std::vector<std::uint8_t>& may = s.contact_rule.may_bond;
  if (s.bond_shadows.active()) {  // a run carrying shadows never bonds itself
    std::fill(may.begin(), may.end(), 0);
    return;
  }
  const std::size_t n = s.bodies.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      may[a * n + b] = may[b * n + a] = bodies::pair_activated(
          s.bodies[a].penetration, s.bodies[b].penetration, s.bond_law.critical_penetration);
}

namespace {

// Steps 1-4 up to the contact decision: the grid, the contact nodes with their normals, and what
// the contact step reads of the points (surfaces, nodal D_bond).
template <class Shape, bool Axisymmetric>
void musl_to_contact(State& s) {
  const int bodies = static_cast<int>(s.bodies.size());
  for (auto& i : s.contact_impulse) i = {0.0, 0.0, 0.0};
  activate_bonding(s);  // where bonds may form this step (§4.1.1, docs/bonding.md)
  bin_points_into_blocks(s);
  s.grid.clear();
  apply_absorbing_dashpots(s);                          // external force, eq 3.46
  map_points_to_grid<Shape, Axisymmetric>(s);           // steps 1-2, eqs 3.23-3.27
  find_contact_nodes<Shape, Axisymmetric>(s);           // multi-mesh at contact nodes
  map_bodies_to_contact_nodes<Shape, Axisymmetric>(s);  //   body-wise m, p, f, grad m
  integrate_grid_momentum(s);                           // step 3, eq 3.28
  choose_contact_normals(s.contact, s.contact_rule,     // step 4, eq 3.30
                         s.constraint, bodies, s.contact_result);
  gather_contact_points<Shape, Axisymmetric>(s);  //   surfaces, nodal D_bond (4.6)
  if (s.contact_rule.debond.enabled)              //   the bonds' areas at the nodes
    spread_bond_areas<Shape, Axisymmetric>(s);
}

// Steps 4-12 from the contact decision on.
template <class Shape, bool Axisymmetric>
void musl_from_contact(State& s) {
  const int bodies = static_cast<int>(s.bodies.size());
  resolve_contact(s.contact, s.contact_rule, s.dt, bodies,  // steps 4-6, eqs 3.29, 3.31
                  s.contact_impulse);
  mark_touching_points<Shape, Axisymmetric>(s);               //   the bonding set S (§4.1.1)
  apply_node_constraints(s, /*force_too=*/true);              //   held nodes stay held
  compute_nodal_velocities(s, /*with_forces=*/true);          //   v = p/m, dv = f dt/m
  update_point_velocities_and_remap<Shape, Axisymmetric>(s);  // steps 7-8, eqs 3.32-3.33
  apply_node_constraints(s, /*force_too=*/false);             //   with the essential BCs
  compute_nodal_velocities(s, /*with_forces=*/false);         //   v = p/m of the re-map
  conduct_heat<Shape, Axisymmetric>(s);                       // Fourier conduction (docs/mpm.md)
  // Steps 9-11, eqs 3.34-3.36 and Appendix A, in one parallel region for all bodies: each thread
  // takes a contiguous share of the bodies' batches of points, and the shares follow the
  // threads' times (mpm/work_shares.hpp).
  WorkShares& shares = s.stress_shares;
  shares.prepare(omp_get_max_threads(), stress_batch_count(s));
  double max_speed = 0.0;
#pragma omp parallel reduction(max : max_speed)
  for (int k = omp_get_thread_num(); k < shares.shares(); k += omp_get_num_threads()) {
    const double start = omp_get_wtime();
    max_speed = std::max(max_speed, update_stress_share<Shape, Axisymmetric>(s, shares.first(k),
                                                                             shares.first(k + 1)));
    shares.record(k, omp_get_wtime() - start);
  }
  shares.rebalance();
  s.max_signal_speed = max_speed;
  account_absorbed_work(s);
  s.displacement_dt = s.dt;
  s.time += s.dt;  // step 12: the grid is reset
  ++s.step;        //   by the next step's clear
}

}  // namespace

void step_to_contact(State& s) {
  with_discretisation(
      s, [&]<class Shape, bool Axisymmetric>() { musl_to_contact<Shape, Axisymmetric>(s); });
}

void step_from_contact(State& s) {
  with_discretisation(
      s, [&]<class Shape, bool Axisymmetric>() { musl_from_contact<Shape, Axisymmetric>(s); });
  bodies::raise_recorded_fault(s);
  if (s.departing > 0) remove_departed_points(s);
  bodies::track_penetration(s);  // bonding's activation for the next step (docs/bonding.md)
}

void step(State& s) {
  step_to_contact(s);
  step_from_contact(s);
}

}  // namespace coldspray::mpm
