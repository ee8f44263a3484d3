// Multi-body grid contact (thesis §3.4 steps 4-6, §3.5.4). Body-wise nodal mass, momentum, force
// and mass gradient are kept only at nodes two or more bodies share (the multi-mesh at contact
// nodes of Ma et al.), so memory grows with the contact area, not with bodies x nodes.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bonding/cohesive_law.hpp"
#include "case/case.hpp"

namespace coldspray::mpm {

// Up to 8: a deposit's ten particles crowd five bodies onto a node (issue 27's ten-particle run
// stopped there with 4).
inline constexpr int kMaxBodiesPerNode = 8;
inline constexpr int kMaxPairsPerNode = kMaxBodiesPerNode * (kMaxBodiesPerNode - 1) / 2;

class ContactNodes {
 public:
  // Slots in use this step.
  std::size_t size() const { return count_; }
  // Forget all slots (keeps capacity).
  void clear() {
    count_ = 0;
    overflow_node_ = kNoOverflow;
  }
  // A new slot for grid node `node`; grows the storage only when its capacity is exceeded.
  std::int32_t add(std::size_t node);
  // The entry of body `b` at slot `s`, added if absent; -1 past kMaxBodiesPerNode, recorded for
  // raise_overflow (points are mapped in parallel, where nothing may throw).
  int entry(std::int32_t s, int b);
  // Throws RunFault naming the lowest grid node that more than kMaxBodiesPerNode bodies reached
  // since clear(), if one did.
  void raise_overflow() const;
  // The entry of body `b` at slot `s`, or -1.
  int find(std::int32_t s, int b) const;

  std::size_t node(std::int32_t s) const { return node_[s]; }
  int body_count(std::int32_t s) const { return body_count_[s]; }
  int body(std::int32_t s, int e) const { return body_[flat(s, e)]; }
  static std::size_t flat(std::int32_t s, int e) {
    return static_cast<std::size_t>(s) * kMaxBodiesPerNode + e;
  }
  // The pair of entries e1 < e2 at slot s, indexing the per-pair arrays.
  static std::size_t pair(std::int32_t s, int e1, int e2) {
    return static_cast<std::size_t>(s) * kMaxPairsPerNode +
           static_cast<std::size_t>(e1 * (2 * kMaxBodiesPerNode - e1 - 1) / 2 + e2 - e1 - 1);
  }

  // Body-wise nodal quantities, indexed by flat(slot, entry).
  std::vector<double> mass;
  std::array<std::vector<double>, 3> momentum;
  std::array<std::vector<double>, 3> force;
  std::array<std::vector<double>, 3> mass_gradient;
  // The momentum the contact step added (eq 3.31 times dt), for the contact work on the points.
  std::array<std::vector<double>, 3> correction;
  // As GridFields::velocity and velocity_change, and the part of the latter contact made,
  // correction/m.
  std::array<std::vector<double>, 3> velocity;
  std::array<std::vector<double>, 3> velocity_change;
  std::array<std::vector<double>, 3> contact_velocity_change;

  // Per pair of entries, indexed by pair(slot, e1, e2): the entry whose normal the pair uses
  // (-1: no normal, the pair is skipped), that unit normal, and the surfaces along it: the
  // furthest reach of the master's points, max (x_p . n + l_p(n)), and the nearest reach of the
  // other body's, min (x_p . n - l_p(n)), l_p(n) the point's half-width along n.
  std::vector<std::int8_t> pair_master;
  std::array<std::vector<double>, 3> pair_normal;
  std::vector<double> master_surface;
  std::vector<double> other_surface;
  // Whether the pair is in contact at the node this step (the surfaces meet, or without the gap
  // check the bodies approach): its bodies' surface points there are in the bonding set S.
  std::vector<std::uint8_t> pair_touching;
  // Bonds kept on the points (Points::bonded_to): bit kLowerSide (kHigherSide) is set when a
  // point of the pair's lower (higher) entry bonded to the other entry's body covers the node.
  // The pair is bonded here when both are (bond_holds).
  std::vector<std::uint8_t> pair_bonded_sides;
  // Whether the pair's nodal D_bond of eq 4.7 reached 1 at the node this step (bond_forms): the
  // surface points of both bodies covering the node are bonded from then on.
  std::vector<std::uint8_t> pair_bond_forms;
  static constexpr std::uint8_t kLowerSide = 1, kHigherSide = 2;
  // The debonding law's view of a pair's bond at the node (bonding/cohesive_law.hpp). Summed over
  // the bonded points of both bodies covering it, each bonded to the other: sum N_I, sum N_I s_p
  // sigma_p, sum N_I s_p (s_p = min(D_bond, 1), sigma_p the point's full-bond strength) and sum
  // N_I d_p (damage), whose weighted means are the node's strength, share of the full fracture
  // energy and damage; and per side (the pair's lower and higher entry) sum N_I. `bond_area` is
  // the bond's area the node carries (mpm/phases.hpp, spread_bond_areas) and `opened_damage` the
  // damage the step's opening added there.
  std::vector<double> bond_weight;
  std::vector<double> bond_strength;
  std::vector<double> bond_share;
  std::vector<double> bond_damage;
  std::array<std::vector<double>, 2> side_weight;
  std::vector<double> bond_area;
  std::vector<double> opened_damage;

  // Per entry, for the nodal bonding parameter (eq 4.6): sum over the body's surface points
  // covering the node of D_bond N_I(x_p), and their number.
  std::vector<double> bond_sum;
  std::vector<std::uint32_t> surface_count;
  std::vector<double> surface_weight;  // and their sum of N_I

 private:
  void grow(std::size_t slots);
  std::size_t count_ = 0;
  static constexpr std::size_t kNoOverflow = static_cast<std::size_t>(-1);
  std::size_t overflow_node_ = kNoOverflow;  // written through std::atomic_ref
  std::vector<std::size_t> node_;
  std::vector<std::uint8_t> body_count_;
  std::vector<std::int16_t> body_;
};

// How the contact normal is chosen at a node, and friction.
struct ContactRule {
  case_file::ContactNormal normal = case_file::ContactNormal::MaxGradient;
  int normal_body = -1;  // with ContactNormal::Body
  // With ContactNormal::Body, the rule at pairs without normal_body (case_file::MpmContact).
  case_file::ContactNormal other_pairs = case_file::ContactNormal::MaxGradient;
  std::vector<double> reference_density;  // per body: MVG compares volume gradients
  double friction = 0.0;
  // Touch only where the surfaces meet (ContactNodes::master_surface, other_surface); without,
  // the thesis' approach test alone.
  bool gap_check = true;
  // The direct bonding model is on: bonded nodes stick (thesis §4.1.1).
  bool bonding = false;
  case_file::NodalAverage nodal_average = case_file::NodalAverage::Weight;  // eq 4.6's divisor
  // Bonding's activation is on (bonding.critical_penetration > 0; docs/bonding.md,
  // "Activation"): an activated pair bonds wherever it touches. Off, eq 4.7 decides where (the
  // thesis).
  bool activation = false;
  // Per ordered body pair [a * bodies + b]: 1 where bonds may form, the pair's impact having
  // penetrated the bond law's critical share (bodies::pair_activated; the stepper refreshes it
  // every step). Empty: every pair may.
  std::vector<std::uint8_t> may_bond;
  bool pair_may_bond(int a, int b, int bodies) const {
    return may_bond.empty() || may_bond[static_cast<std::size_t>(a * bodies + b)] != 0;
  }
  // With bonding, what a bond carries before it lets go (`bonding.debond`); disabled, a bond
  // holds for good.
  bonding::CohesiveLaw debond;
  double mass_floor = 0.0;  // kg: lighter nodes carry no velocity (State::mass_floor)
};

// The MVG choice of master bodies, kept from step to step, and its per-step scratch.
struct ContactResult {
  // Per ordered body pair [a * bodies + b]: sum over the nodes they share of |grad m_a| / rho_a,
  // the weight that decides the pair's MVG master body.
  std::vector<double> gradient_weight;
  // Per ordered pair: 1 while a is the pair's MVG master, kept from step to step.
  std::vector<std::uint8_t> master;
};

// For every pair of bodies at every contact node: which body's normal the pair uses (thesis
// §3.5.4, `rule.normal`) and the unit normal from its mass gradient (eq 3.30). `held` is the
// grid's NodeConstraint bits: a held velocity component (a symmetry or roller plane through the
// node) is removed from the normal, which cannot point through that plane. Resets the surfaces
// for the gap measurement (mpm/phases.hpp, gather_contact_points).
void choose_contact_normals(ContactNodes& contact, const ContactRule& rule,
                            const std::vector<std::uint8_t>& held, int bodies,
                            ContactResult& result);

// For every pair with a normal, in a fixed order: the approach test (eq 3.29), with the gap check
// the surfaces meeting by the end of the step, and then the sticking correction (eq 3.31)
// reduced to its normal part, with a Coulomb-limited tangential part when friction > 0. Where
// the pair is bonded (a bond forms there, where an activated pair touches or, without
// activation, where its nodal D_bond of eq 4.7 >= 1; or one kept on the points holds) the
// correction is applied in full, normal and tangential, approaching or not: the bond
// force; with a debonding law, only up to the traction the bond's points can carry there, the
// rest opening the bond (contact.opened_damage). Each correction changes the two bodies' momenta
// by equal and opposite amounts, and their forces by the same over dt; `impulse`
// (bodies::Bodies::contact_impulse) sums them per ordered body pair.
void resolve_contact(ContactNodes& contact, const ContactRule& rule, double dt, int bodies,
                     std::vector<std::array<double, 3>>& impulse);

// Adds a surface point's share D_bond N_I(x_p) to an entry's sum of eq 4.6. The run's sums and a
// bond family's shadows of them (mpm/bond_shadows.hpp) both add through here, so that, with
// multiply-adds fused in the solver (CMakeLists.txt), a shadow rounds exactly as the run it
// stands for: one fused rounding where the processor has FMA, two roundings where it has not.
inline void add_bond_share(double& sum, double bond, double weight) {
#ifdef __FMA__
  sum = std::fma(bond, weight, sum);
#else
  sum += bond * weight;
#endif
}

// Eqs 4.6-4.7: the pair's global nodal bonding parameter, the mean of the two bodies' nodal
// values, each sum_p D_bond N_I over its surface points covering the node divided by their
// number n_sp (the thesis) or by their sum of N_I (`average`). `bond_sum` is contact.bond_sum or
// sums laid out like it (mpm/bond_shadows.hpp).
double nodal_bond(const ContactNodes& contact, const std::vector<double>& bond_sum,
                  std::int32_t slot, int e1, int e2, case_file::NodalAverage average);
inline double nodal_bond(const ContactNodes& contact, std::int32_t slot, int e1, int e2,
                         case_file::NodalAverage average) {
  return nodal_bond(contact, contact.bond_sum, slot, e1, e2, average);
}

// Eq 4.7's criterion: a bond forms at a node where the pair's nodal D_bond reaches 1.
inline bool bond_forms(double nodal_bond_value) { return nodal_bond_value >= 1.0; }

// Whether the bond kept on the points holds at a node: bonded points of both bodies reach it. A
// point lets go of its bond when its damage under the debonding law reaches 1 (damage_bond in
// mpm/phases.hpp); without one, a bond, once formed, always holds.
inline bool bond_holds(std::uint8_t bonded_sides) {
  return bonded_sides == (ContactNodes::kLowerSide | ContactNodes::kHigherSide);
}

}  // namespace coldspray::mpm
