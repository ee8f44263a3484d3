// The phases of one MUSL step (thesis §3.4), each a loop over points or nodes. Templated on the
// shape function and on the geometry (3D or axisymmetric r-z) so the inner loops are tight.
// Point-to-grid phases run block by block (State::Blocks) so they are race-free and deterministic;
// grid-to-point phases write only their own point.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "bodies/grip.hpp"
#include "bodies/point_area.hpp"
#include "bonding/cohesive_law.hpp"
#include "core/double4.hpp"
#include "materials/stress_update.hpp"
#include "mpm/state.hpp"
#include "mpm/stencil.hpp"

namespace coldspray::mpm {

// Calls f(p) for every point: the blocks of one colour in parallel, colour after colour.
template <class F>
void for_each_point_by_block(const Blocks& blocks, F&& f) {
  const auto per_colour = static_cast<long>(blocks.per_colour);
  for (long colour = 0; colour < Blocks::kColours; ++colour) {
    const long first = colour * per_colour, last = first + per_colour;
    if (blocks.begin[first] == blocks.begin[last]) continue;  // (r-z: the odd strips)
#pragma omp parallel for schedule(dynamic, 1)
    for (long b = first; b < last; ++b)
      for (std::size_t i = blocks.begin[b]; i < blocks.begin[b + 1]; ++i) f(blocks.order[i]);
  }
}

// What one point gives the grid: mass, momentum and the force of eqs 3.25-3.26, with the
// artificial viscous pressure q added to the stress and, in r-z, the hoop-stress term
// -V sigma_tt N / r of the divergence in cylindrical coordinates.
template <bool Axisymmetric>
struct PointContribution {
  double m, mv[3], Vs[6], fext[3], hoop;

  PointContribution(const State& s, std::size_t p) {
    const Points& P = s.points;
    m = P.mass[p];
    for (int d = 0; d < 3; ++d) {
      mv[d] = m * P.velocity[d][p];
      fext[d] = s.external_force[d][p];
    }
    const double V = P.volume0[p] * P.J[p];
    const double q = P.bulk_viscosity[p];
    for (int c = 0; c < 6; ++c) Vs[c] = V * (P.stress[c][p] - (c < 3 ? q : 0.0));
    hoop = Axisymmetric ? Vs[bodies::kYY] / P.position[0][p] : 0.0;
  }

  void force(double w, double gx, double gy, double gz, double f[3]) const {
    f[0] = w * fext[0] - (Vs[bodies::kXX] * gx + Vs[bodies::kXY] * gy + Vs[bodies::kXZ] * gz);
    if constexpr (Axisymmetric) f[0] -= w * hoop;
    f[1] = w * fext[1] - (Vs[bodies::kXY] * gx + Vs[bodies::kYY] * gy + Vs[bodies::kYZ] * gz);
    f[2] = w * fext[2] - (Vs[bodies::kXZ] * gx + Vs[bodies::kYZ] * gy + Vs[bodies::kZZ] * gz);
  }
};

// Point p's stencil, as map_points_to_grid evaluated it this step.
template <class Shape, bool Axisymmetric>
const Stencil<Shape, Axisymmetric>& stencil_of(const State& s, std::size_t p) {
  return std::get<std::vector<Stencil<Shape, Axisymmetric>>>(s.stencils)[p];
}

// Steps 1-2 (eqs 3.23-3.27): nodal mass, momentum and force, summed over all bodies; and which
// bodies reach each node, to find the contact nodes. Evaluates every point's stencil for the
// step (State::stencils).
template <class Shape, bool Axisymmetric>
void map_points_to_grid(State& s) {
  GridFields& g = s.grid;
  auto& stencils = std::get<std::vector<Stencil<Shape, Axisymmetric>>>(s.stencils);
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    Stencil<Shape, Axisymmetric>& st = stencils[p];
    st.evaluate(s.layout, s.points, p);
    const PointContribution<Axisymmetric> c(s, p);
    const int b = s.points.body[p];
    st.for_each(s.layout, [&](std::size_t n, double w, double gx, double gy, double gz) {
      double f[3];
      c.force(w, gx, gy, gz, f);
      NodeSums& node = g.sums[n];
      node.mass += w * c.m;
      for (int d = 0; d < 3; ++d) {
        node.momentum[d] += w * c.mv[d];
        node.force[d] += f[d];
      }
      // A body reaches the nodes where its points weigh: counting a node of zero weight would
      // widen every contact band by a node layer. GIMP's stencils no longer hold such nodes
      // (drop_empty_end_nodes); a linear hat does, with a non-zero gradient, when its point sits
      // on a node. (One word per node: a byte-wide flag here would alias every array of the
      // loop.)
      if (w == 0.0) return;
      const std::int32_t seen = g.reached_by[n];
      if (seen == GridFields::kNoBody)
        g.reached_by[n] = b;
      else if (seen != b)
        g.reached_by[n] = GridFields::kManyBodies;
    });
  });
}

// Whether a stencil reaches a contact node: find_contact_nodes flags the lowest nodes of the
// stencils that do.
template <class Stencil>
bool near_contact(const State& s, const Stencil& st) {
  return s.near_contact[s.layout.index(st.wx.base, st.wy.base, st.wz.base)] != 0;
}

// The multi-mesh at contact nodes: the same sums as map_points_to_grid, kept per body, plus
// each body's mass gradient (eq 3.30), only at the nodes two or more bodies share.
template <class Shape, bool Axisymmetric>
void map_bodies_to_contact_nodes(State& s) {
  if (s.contact.size() == 0) return;
  ContactNodes& cn = s.contact;
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    if (!near_contact(s, st)) return;
    const PointContribution<Axisymmetric> c(s, p);
    // The point's weight in the body's normal of eq 3.30. In r-z m is a ring's mass, 2 pi r rho A,
    // which grows with r: summed with grad N_I it tilts a flat face's normal towards the axis by
    // atan(h / 2r), so a frictionless interface resists radial slip (the r-z impact then deformed
    // as if welded, against the 3D model's free slip, issue 22). The normal is that of the body's
    // cross-section, the gradient of its density in the r-z plane: m / r weighs it.
    const double m_normal = Axisymmetric ? c.m / s.points.position[0][p] : c.m;
    const int b = s.points.body[p];
    st.for_each(s.layout, [&](std::size_t n, double w, double gx, double gy, double gz) {
      const std::int32_t slot = s.grid.contact_slot[n];
      if (slot < 0 || w == 0.0) return;  // (a body has an entry only where it weighs)
      const int entry = cn.entry(slot, b);
      if (entry < 0) return;  // one body too many: raised below
      const std::size_t e = ContactNodes::flat(slot, entry);
      double f[3];
      c.force(w, gx, gy, gz, f);
      const double grad[3] = {gx, gy, gz};
      cn.mass[e] += w * c.m;
      for (int d = 0; d < 3; ++d) {
        cn.momentum[d][e] += w * c.mv[d];
        cn.force[d][e] += f[d];
        cn.mass_gradient[d][e] += m_normal * grad[d];
      }
    });
  });
  cn.raise_overflow();
}

// A point of entry e, bonded to body `partner`, covers the node at `slot`: its side of the pair
// with the partner's entry is bonded there (ContactNodes::pair_bonded_sides). Returns the pair
// (-1 where the partner has no entry) and whether e is its lower entry.
struct BondedSide {
  std::ptrdiff_t pair = -1;
  bool lower = false;
};
inline BondedSide mark_bonded_side(ContactNodes& cn, std::int32_t slot, int e, int partner) {
  const int o = cn.find(slot, partner);
  if (o < 0 || o == e) return {};
  const std::size_t k = ContactNodes::pair(slot, std::min(e, o), std::max(e, o));
  cn.pair_bonded_sides[k] |= e < o ? ContactNodes::kLowerSide : ContactNodes::kHigherSide;
  return {static_cast<std::ptrdiff_t>(k), e < o};
}

// A bonded point's share, weight w = N_I(x_p), of the debonding law's sums at pair k
// (ContactNodes::bond_weight and after).
inline void add_to_bond_sums(ContactNodes& cn, const bonding::CohesiveLaw& law, const Points& P,
                             std::size_t p, std::size_t k, bool lower_side, double w) {
  const double share = w * bonding::bonded_share(P.bond[p]);
  cn.bond_weight[k] += w;
  cn.bond_strength[k] += share * law.full_strength(P.flow_stress[p]);
  cn.bond_share[k] += share;
  cn.bond_damage[k] += w * P.bond_damage[p];
  cn.side_weight[lower_side ? 0 : 1][k] += w;
}

// What the contact step needs from the points near contact nodes. For the gap check: along each
// pair's normal, the furthest reach of the master body's points (x_p . n plus the point's
// half-width along n) and the nearest reach of the other's, over the points covering the node.
// For bonding: each body's sum of D_bond N_I over its surface points there, and their number
// (eq 4.6), the same sums for the bond laws the run shadows, and which sides of each pair have
// bonded points there. Minima and maxima are exact in any order, the sums run in block order, and
// the block colouring keeps threads off each other's nodes.
template <class Shape, bool Axisymmetric>
void gather_contact_points(State& s) {
  const bool gap = s.contact_rule.gap_check, bonding = s.contact_rule.bonding;
  const bonding::CohesiveLaw& debond = s.contact_rule.debond;
  if (s.contact.size() == 0 || !(gap || bonding)) return;
  ContactNodes& cn = s.contact;
  const Points& P = s.points;
  BondShadows& shadows = s.bond_shadows;
  const bool shadowing = bonding && shadows.active();
  if (shadowing) shadows.clear_sums(cn);
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    if (!near_contact(s, st)) return;
    const int b = P.body[p];
    st.for_each(s.layout, [&](std::size_t node, double w, double, double, double) {
      const std::int32_t slot = s.grid.contact_slot[node];
      if (slot < 0 || w == 0.0) return;
      const int e = cn.find(slot, b);
      if (bonding && P.surface[p]) {
        const std::size_t f = ContactNodes::flat(slot, e);
        // A point whose bond broke counts as unbonded towards a new one (bond_damage).
        add_bond_share(cn.bond_sum[f], P.bond_damage[p] >= 1.0 ? 0.0 : P.bond[p], w);
        ++cn.surface_count[f];
        cn.surface_weight[f] += w;
        if (shadowing) shadows.add_to_sums(p, f, w);
        if (P.bonded_to[p] != 0) {
          const BondedSide side = mark_bonded_side(cn, slot, e, P.bonded_to[p] - 1);
          if (side.pair >= 0 && debond.enabled)
            add_to_bond_sums(cn, debond, P, p, static_cast<std::size_t>(side.pair), side.lower, w);
        }
      }
      if (!gap) return;
      for (int o = 0; o < cn.body_count(slot); ++o) {
        if (o == e) continue;
        const std::size_t k = ContactNodes::pair(slot, std::min(e, o), std::max(e, o));
        if (cn.pair_master[k] < 0) continue;
        double along = 0.0, reach = 0.0;
        for (int d = 0; d < 3; ++d) {
          along += P.position[d][p] * cn.pair_normal[d][k];
          reach += P.half_width[d][p] * std::abs(cn.pair_normal[d][k]);
        }
        if (cn.pair_master[k] == e)
          cn.master_surface[k] = std::max(cn.master_surface[k], along + reach);
        else
          cn.other_surface[k] = std::min(cn.other_surface[k], along - reach);
      }
    });
  });
}

// How much of a bonded point's bond passes through the node at `slot`, per unit N_I, where its
// entry e meets its partner's entry o: the partner side's share of the bonded weight there,
// W_o / (W_e + W_o), 0 where the pair is not bonded. The force between the bodies passes where
// both have material: a flat interface on a node layer carries it all on that layer, where each
// side puts three quarters of its points' weight and the other side as much, while the layers
// beyond, which one side alone reaches, carry none (tests/mpm/debond_test.cpp).
inline double bond_passage(const ContactNodes& cn, std::size_t k, int e, int o) {
  if (!bond_holds(cn.pair_bonded_sides[k])) return 0.0;
  const double own = cn.side_weight[e < o ? 0 : 1][k], other = cn.side_weight[e < o ? 1 : 0][k];
  return other / (own + other);
}

// Calls f(k, N_I bond_passage) for each node where a bonded point's bond passes, k its pair.
template <class Stencil, class F>
void for_each_bond_node(const State& s, const Stencil& st, std::size_t p, F&& f) {
  const ContactNodes& cn = s.contact;
  const int b = s.points.body[p], partner = s.points.bonded_to[p] - 1;
  st.for_each(s.layout, [&](std::size_t node, double w, double, double, double) {
    const std::int32_t slot = s.grid.contact_slot[node];
    if (slot < 0 || w == 0.0) return;
    const int e = cn.find(slot, b), o = cn.find(slot, partner);
    if (o < 0) return;
    const std::size_t k = ContactNodes::pair(slot, std::min(e, o), std::max(e, o));
    const double passage = w * bond_passage(cn, k, e, o);
    if (passage > 0.0) f(k, passage);
  });
}

// The debonding law's area of the bond at each node (ContactNodes::bond_area): each bonded
// point's surface area a_p spread over the nodes where its bond passes, in proportion to N_I
// bond_passage, and both sides' shares averaged. Over a pair's nodes the areas add up to the mean
// of its two sides' bonded areas. In block order, as the other point-to-grid phases.
template <class Shape, bool Axisymmetric>
void spread_bond_areas(State& s) {
  ContactNodes& cn = s.contact;
  const Points& P = s.points;
  if (cn.size() == 0) return;
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    if (P.bonded_to[p] == 0) return;
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    if (!near_contact(s, st)) return;
    double total = 0.0;
    for_each_bond_node(s, st, p, [&](std::size_t, double passage) { total += passage; });
    if (total == 0.0) return;
    const double half_area = 0.5 * bodies::point_area(P, p, Axisymmetric) / total;
    for_each_bond_node(
        s, st, p, [&](std::size_t k, double passage) { cn.bond_area[k] += half_area * passage; });
  });
}

// The damage the step's opening added to a bonded point's bond: that of the node carrying most of
// it, the largest N_I bond_passage (ContactNodes::opened_damage; the small shares at the layers
// one side barely reaches hold rigidly and, averaged in, slowed the damage by 12 %). At damage 1,
// or where its bond passes no node any more (its partner's bonded points no longer meet it: the
// bond opened beyond the grid's reach or let go on the other side), the point lets go of it.
template <class Stencil>
void damage_bond(State& s, const Stencil& st, std::size_t p) {
  Points& P = s.points;
  double largest = 0.0, opened = 0.0;
  for_each_bond_node(s, st, p, [&](std::size_t k, double passage) {
    if (passage <= largest) return;
    largest = passage;
    opened = s.contact.opened_damage[k];
  });
  P.bond_damage[p] = largest > 0.0 ? std::min(1.0, P.bond_damage[p] + opened) : 1.0;
  if (P.bond_damage[p] >= 1.0) P.bonded_to[p] = 0;
}

// The bonding set S (thesis §4.1.1): a surface point is in contact this step where a node it
// covers has its body touching another (ContactNodes::pair_touching); its contact normal, the
// weighted mean of those pairs' normals turned outward from its own body, orients the shear
// part of its plastic strain (bonding/bond_law.hpp). A surface point covering a node where a bond
// formed this step (ContactNodes::pair_bond_forms: it entered that node's eq 4.6) keeps the bond
// to the other body from then on (Points::bonded_to), so that the bond no longer depends on which
// points the moving material brings to the node, unless its own bond broke before. With the
// debonding law, a bonded point first takes its bond's damage (damage_bond). Writes only its own
// point.
template <class Shape, bool Axisymmetric>
void mark_touching_points(State& s) {
  if (!s.contact_rule.bonding) return;
  Points& P = s.points;
  const ContactNodes& cn = s.contact;
  const bool debond = s.contact_rule.debond.enabled;
  const long n = static_cast<long>(P.size());
#pragma omp parallel for schedule(static)
  for (long pi = 0; pi < n; ++pi) {
    const auto p = static_cast<std::size_t>(pi);
    P.touching[p] = 0;
    if (!P.surface[p]) continue;
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    if (debond && P.bonded_to[p] != 0) damage_bond(s, st, p);
    if (cn.size() == 0 || !near_contact(s, st)) continue;
    const int b = P.body[p];
    double normal[3] = {0.0, 0.0, 0.0};
    st.for_each(s.layout, [&](std::size_t node, double w, double, double, double) {
      const std::int32_t slot = s.grid.contact_slot[node];
      if (slot < 0 || w == 0.0) return;
      const int e = cn.find(slot, b);
      for (int o = 0; o < cn.body_count(slot); ++o) {
        if (o == e) continue;
        const std::size_t k = ContactNodes::pair(slot, std::min(e, o), std::max(e, o));
        if (cn.pair_bond_forms[k] && P.bonded_to[p] == 0 && P.bond_damage[p] < 1.0)
          P.bonded_to[p] = static_cast<std::uint16_t>(cn.body(slot, o) + 1);
        if (!cn.pair_touching[k]) continue;
        P.touching[p] = 1;
        const double outward = cn.pair_master[k] == e ? w : -w;
        for (int d = 0; d < 3; ++d) normal[d] += outward * cn.pair_normal[d][k];
      }
    });
    const double norm =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (int d = 0; d < 3; ++d) P.contact_normal[d][p] = norm > 0.0 ? normal[d] / norm : 0.0;
  }
}

// Eq 3.32's nodal velocities v = p/m and, `with_forces`, the step's velocity change f dt/m and
// the part of it contact made, correction/m: on the grid and per body at contact nodes, each
// divided once here rather than at every point that reads it. Nodes lighter than the mass
// floor carry no velocity: zero.
inline void compute_nodal_velocities(State& s, bool with_forces) {
  GridFields& g = s.grid;
  const long nodes = static_cast<long>(s.layout.node_count());
  const double dt = s.dt, floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) {
    const NodeSums& sums = g.sums[n];
    NodeMotion& motion = g.motion[n];
    const bool moves = sums.mass > floor;
    for (int d = 0; d < 3; ++d) {
      motion.velocity[d] = moves ? sums.momentum[d] / sums.mass : 0.0;
      if (with_forces) motion.velocity_change[d] = moves ? sums.force[d] * dt / sums.mass : 0.0;
    }
  }
  ContactNodes& c = s.contact;
  for (std::size_t slot = 0; slot < c.size(); ++slot)
    for (int e = 0; e < c.body_count(static_cast<std::int32_t>(slot)); ++e) {
      const std::size_t i = ContactNodes::flat(static_cast<std::int32_t>(slot), e);
      const bool moves = c.mass[i] > floor;
      for (int d = 0; d < 3; ++d) {
        c.velocity[d][i] = moves ? c.momentum[d][i] / c.mass[i] : 0.0;
        if (!with_forces) continue;
        c.velocity_change[d][i] = moves ? c.force[d][i] * dt / c.mass[i] : 0.0;
        c.contact_velocity_change[d][i] = moves ? c.correction[d][i] / c.mass[i] : 0.0;
      }
    }
}

// The nodal velocities a point of body b sees at node n: its own body's at a contact node, the
// grid's elsewhere.
struct NodeView {
  double v[3];           // p/m
  double dv[3];          // f dt/m
  double dv_contact[3];  // correction/m (0 away from contact nodes)
};

// The grid's nodal velocities at node n: what every body sees away from contact nodes.
inline NodeView grid_node_view(const State& s, std::size_t n) {
  NodeView v;
  const NodeMotion& motion = s.grid.motion[n];
  for (int d = 0; d < 3; ++d) {
    v.v[d] = motion.velocity[d];
    v.dv[d] = motion.velocity_change[d];
    v.dv_contact[d] = 0.0;
  }
  return v;
}

inline NodeView node_view(const State& s, std::size_t n, int b) {
  NodeView v;
  const std::int32_t slot = s.grid.contact_slot[n];
  const int e = slot < 0 ? -1 : s.contact.find(slot, b);
  if (e < 0) {
    v = grid_node_view(s, n);
  } else {
    const std::size_t i = ContactNodes::flat(slot, e);
    for (int d = 0; d < 3; ++d) {
      v.v[d] = s.contact.velocity[d][i];
      v.dv[d] = s.contact.velocity_change[d][i];
      v.dv_contact[d] = s.contact.contact_velocity_change[d][i];
    }
  }
  return v;
}

// Calls f(node, N, dN/dx, dN/dy, dN/dz, view) over a stencil of a point of body b, `view` the
// nodal velocities the point sees (node_view). A point not near contact, as most are, reads the
// grid's without looking each node up among the contact nodes. (Inlined: called out of line, the
// point's sums that f adds to went through memory and the re-map took 10 % longer.)
template <class Stencil, class F>
[[gnu::always_inline]] inline void for_each_node_view(const State& s, const Stencil& st, bool near,
                                                      int b, F&& f) {
  if (near)
    st.for_each(s.layout, [&](std::size_t n, double w, double gx, double gy, double gz) {
      f(n, w, gx, gy, gz, node_view(s, n, b));
    });
  else
    st.for_each(s.layout, [&](std::size_t n, double w, double gx, double gy, double gz) {
      f(n, w, gx, gy, gz, grid_node_view(s, n));
    });
}

// Steps 7-8 (eqs 3.32-3.33) in one pass over the points. Step 7: the point's velocity from the
// nodal forces, and its displacement from the nodal velocities after contact, applied once the
// strain increment has used the old positions. The work the contact corrections do on the point,
// m (v + dv/2) . dv_contact, is its share of the step's kinetic-energy change: the contact term
// of the energy budget. Step 8, the MUSL re-map: the nodal momenta again from the updated point
// velocities, total and per body at contact nodes. A point's re-mapped momentum needs only its
// own new velocity, so both steps share its stencil; the re-map fills the momentum arrays, which
// step 7 does not read (it reads the velocities derived from them). A point the pull-off test's
// grip holds takes the grip's velocity and motion instead (bodies/grip.hpp).
template <class Shape, bool Axisymmetric>
void update_point_velocities_and_remap(State& s) {
  GridFields& g = s.grid;
  ContactNodes& cn = s.contact;
  Points& P = s.points;
  const long nodes = static_cast<long>(g.sums.size());
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) g.sums[n].momentum = {0.0, 0.0, 0.0};
  const std::size_t used = cn.size() * kMaxBodiesPerNode;
  for (auto& a : cn.momentum) std::fill_n(a.begin(), used, 0.0);
  const double dt = s.dt;
  // The grip's velocity at the step's start and end (bodies/grip.hpp).
  const Eigen::Vector3d grip_from = bodies::grip_velocity_at(s, s.time);
  const Eigen::Vector3d grip_to = bodies::grip_velocity_at(s, s.time + dt);
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    const int b = P.body[p];
    const double m = P.mass[p];
    const bool near = near_contact(s, st);
    // The sums as four-double vectors (last lane unused): three multiply-adds per node.
    Double4 dv = {0.0, 0.0, 0.0, 0.0}, v = dv, dv_contact = dv;
    for_each_node_view(
        s, st, near, b, [&](std::size_t, double w, double, double, double, const NodeView& node) {
          dv += w * Double4{node.dv[0], node.dv[1], node.dv[2], 0.0};
          v += w * Double4{node.v[0], node.v[1], node.v[2], 0.0};
          dv_contact +=
              w * Double4{node.dv_contact[0], node.dv_contact[1], node.dv_contact[2], 0.0};
        });
    double v_new[3];
    for (int d = 0; d < 3; ++d) {
      P.contact_work[p] += m * (P.velocity[d][p] + 0.5 * dv[d]) * dv_contact[d];
      v_new[d] = P.velocity[d][p] += dv[d];
      P.displacement[d][p] = v[d] * dt;
    }
    // A gripped point moves with the grip, whatever the grid gives it; the kinetic energy the
    // grip adds goes to the budget's contact entry, as PD books it (pd/stepper.cpp).
    if (s.gripped[p])
      for (int d = 0; d < 3; ++d) {
        P.contact_work[p] += 0.5 * m * (grip_to[d] * grip_to[d] - v_new[d] * v_new[d]);
        v_new[d] = P.velocity[d][p] = grip_to[d];
        P.displacement[d][p] = 0.5 * (grip_from[d] + grip_to[d]) * dt;
      }
    st.for_each(s.layout, [&](std::size_t n, double w, double, double, double) {
      const double wm = w * m;
      for (int d = 0; d < 3; ++d) g.sums[n].momentum[d] += wm * v_new[d];
      if (!near || w == 0.0) return;
      const std::int32_t slot = g.contact_slot[n];
      if (slot < 0) return;
      // Where it weighs, a point near a contact node got its entry in
      // map_bodies_to_contact_nodes.
      const std::size_t e = ContactNodes::flat(slot, cn.find(slot, b));
      for (int d = 0; d < 3; ++d) cn.momentum[d][e] += wm * v_new[d];
    });
  });
}

// Steps 9-11 (eqs 3.34-3.36, Appendix A) for batches [first, end) of the step's batches of
// points (each body's points in batches of materials::kBatchPoints, body after body): velocity
// gradient from the nodal velocities, density, artificial viscosity, the material's stress
// update; then the position update. Threads may call it for disjoint ranges at once; returns the
// largest c + |v| of the range's points.
template <class Shape, bool Axisymmetric>
double update_stress_share(State& s, std::size_t first, std::size_t end);
// The number of those batches.
std::size_t stress_batch_count(const State& s);

}  // namespace coldspray::mpm
