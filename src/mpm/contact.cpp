#include "mpm/contact.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace coldspray::mpm {

using Eigen::Vector3d;

std::int32_t ContactNodes::add(std::size_t node) {
  if (count_ == node_.size()) grow(std::max<std::size_t>(1024, 2 * node_.size()));
  const auto s = static_cast<std::int32_t>(count_++);
  node_[s] = node;
  body_count_[s] = 0;
  for (int e = 0; e < kMaxBodiesPerNode; ++e) {
    const std::size_t f = flat(s, e);
    mass[f] = bond_sum[f] = surface_weight[f] = 0.0;
    surface_count[f] = 0;
    for (int d = 0; d < 3; ++d)
      momentum[d][f] = force[d][f] = mass_gradient[d][f] = correction[d][f] = 0.0;
  }
  return s;
}

int ContactNodes::find(std::int32_t s, int b) const {
  for (int e = 0; e < body_count_[s]; ++e)
    if (body_[flat(s, e)] == b) return e;
  return -1;
}

int ContactNodes::entry(std::int32_t s, int b) {
  const int found = find(s, b);
  if (found >= 0) return found;
  const int e = body_count_[s];
  if (e == kMaxBodiesPerNode) {
    std::atomic_ref<std::size_t> overflow(overflow_node_);
    std::size_t lowest = overflow.load();
    while (node_[s] < lowest && !overflow.compare_exchange_weak(lowest, node_[s])) {
    }
    return -1;
  }
  body_[flat(s, e)] = static_cast<std::int16_t>(b);
  body_count_[s] = static_cast<std::uint8_t>(e + 1);
  return e;
}

void ContactNodes::raise_overflow() const {
  const std::size_t node = overflow_node_;
  if (node != kNoOverflow)
    throw RunFault(
        fmt::format("more than {} bodies meet at grid node {}: the contact holds no more "
                    "(mpm/contact.hpp)",
                    kMaxBodiesPerNode, node));
}

void ContactNodes::grow(std::size_t slots) {
  node_.resize(slots);
  body_count_.resize(slots);
  body_.resize(slots * kMaxBodiesPerNode);
  mass.resize(slots * kMaxBodiesPerNode);
  for (auto* a : {&momentum, &force, &mass_gradient, &correction, &velocity, &velocity_change,
                  &contact_velocity_change})
    for (auto& v : *a) v.resize(slots * kMaxBodiesPerNode);
  pair_master.resize(slots * kMaxPairsPerNode);
  for (auto& v : pair_normal) v.resize(slots * kMaxPairsPerNode);
  master_surface.resize(slots * kMaxPairsPerNode);
  other_surface.resize(slots * kMaxPairsPerNode);
  pair_touching.resize(slots * kMaxPairsPerNode);
  pair_bonded_sides.resize(slots * kMaxPairsPerNode);
  pair_bond_forms.resize(slots * kMaxPairsPerNode);
  for (auto* v : {&bond_weight, &bond_strength, &bond_share, &bond_damage, &side_weight[0],
                  &side_weight[1], &bond_area, &opened_damage})
    v->resize(slots * kMaxPairsPerNode);
  bond_sum.resize(slots * kMaxBodiesPerNode);
  surface_count.resize(slots * kMaxBodiesPerNode);
  surface_weight.resize(slots * kMaxBodiesPerNode);
}

namespace {

Vector3d load(const std::array<std::vector<double>, 3>& a, std::size_t f) {
  return {a[0][f], a[1][f], a[2][f]};
}

void add_to(std::array<std::vector<double>, 3>& a, std::size_t f, const Vector3d& v) {
  for (int d = 0; d < 3; ++d) a[d][f] += v[d];
}

// Sums each body's volume gradient |grad m| / rho0 over the nodes it shares with each other
// body: the maximum volume gradient (MVG) is decided per body pair over their whole contact.
void weigh_gradients(const ContactNodes& c, const ContactRule& rule, int bodies,
                     std::vector<double>& weight) {
  std::fill(weight.begin(), weight.end(), 0.0);
  for (std::size_t s = 0; s < c.size(); ++s) {
    const auto slot = static_cast<std::int32_t>(s);
    for (int e1 = 0; e1 < c.body_count(slot); ++e1)
      for (int e2 = 0; e2 < c.body_count(slot); ++e2) {
        if (e1 == e2) continue;
        const int b = c.body(slot, e1), o = c.body(slot, e2);
        weight[b * bodies + o] +=
            load(c.mass_gradient, ContactNodes::flat(slot, e1)).norm() / rule.reference_density[b];
      }
  }
}

// The rule at the pair of bodies b1, b2: `body:NAME` is the named body's normal where it is one of
// the two, rule.other_pairs elsewhere.
case_file::ContactNormal pair_rule(const ContactRule& rule, int b1, int b2) {
  if (rule.normal != case_file::ContactNormal::Body || b1 == rule.normal_body ||
      b2 == rule.normal_body)
    return rule.normal;
  return rule.other_pairs;
}

// MVG hands the normal to the other body of a pair only when its volume gradient exceeds the
// master's by this factor, so that near-ties do not flip the normal from step to step.
constexpr double kMasterSwitchRatio = 1.1;

// Whether body b1 supplies the contact normal against b2 (thesis §3.5.4). MVG takes the body
// with the larger volume gradient over the pair's shared nodes, not node by node, and keeps it
// through near-ties: a normal that flips between the bodies from node to node or from step to
// step makes the contact dissipate (two elastic spheres rebounded at 41.5 of 50 m/s with a
// node-by-node choice, at 33 m/s with a step-by-step one, at 49.1 m/s with a fixed master).
bool first_is_master(const ContactRule& rule, const std::vector<double>& weight, int bodies, int b1,
                     int b2, std::vector<std::uint8_t>& master) {
  switch (pair_rule(rule, b1, b2)) {
    case case_file::ContactNormal::Body:
      return b1 == rule.normal_body;
    case case_file::ContactNormal::HighestId:
      return b1 > b2;
    case case_file::ContactNormal::AverageGradient:
      return b1 > b2;  // the normal is both bodies'; the master only orients it
    case case_file::ContactNormal::MaxGradient:
      break;
  }
  const double w1 = weight[b1 * bodies + b2], w2 = weight[b2 * bodies + b1];
  std::uint8_t& one = master[b1 * bodies + b2];
  std::uint8_t& two = master[b2 * bodies + b1];
  if (!one && !two) {  // first contact of the pair
    one = w1 > w2 || (w1 == w2 && b1 > b2);
    two = !one;
  } else if (one && w2 > kMasterSwitchRatio * w1) {
    one = 0;
    two = 1;
  } else if (two && w1 > kMasterSwitchRatio * w2) {
    one = 1;
    two = 0;
  }
  return one;
}

// The gradient whose direction is the pair's normal, outward of the master: the master's mass
// gradient (eq 3.30), or with `average-gradient` the master's volume gradient less the other's
// (thesis §3.5.4: "a function of the two may be selected as the contact normal"; NairnMPM's
// average volume gradient for two materials, its "avggrad" normal): at a flat interface the two
// are opposite and it is either body's normal; where
// the bodies' gradients disagree (an edge, a curved contact, a third body nearby) it takes the
// plane between them, whichever body is numbered higher.
Vector3d pair_gradient(const ContactNodes& c, const ContactRule& rule, std::int32_t slot,
                       int master, int other) {
  const Vector3d g_master = load(c.mass_gradient, ContactNodes::flat(slot, master));
  if (pair_rule(rule, c.body(slot, master), c.body(slot, other)) !=
      case_file::ContactNormal::AverageGradient)
    return g_master;
  const Vector3d g_other = load(c.mass_gradient, ContactNodes::flat(slot, other));
  return g_master / rule.reference_density[c.body(slot, master)] -
         g_other / rule.reference_density[c.body(slot, other)];
}

}  // namespace

void choose_contact_normals(ContactNodes& c, const ContactRule& rule,
                            const std::vector<std::uint8_t>& held, int bodies,
                            ContactResult& result) {
  weigh_gradients(c, rule, bodies, result.gradient_weight);
  for (std::size_t s = 0; s < c.size(); ++s) {
    const auto slot = static_cast<std::int32_t>(s);
    for (int e1 = 0; e1 < c.body_count(slot); ++e1)
      for (int e2 = e1 + 1; e2 < c.body_count(slot); ++e2) {
        const std::size_t k = ContactNodes::pair(slot, e1, e2);
        const int master = first_is_master(rule, result.gradient_weight, bodies, c.body(slot, e1),
                                           c.body(slot, e2), result.master)
                               ? e1
                               : e2;
        const int other = master == e1 ? e2 : e1;
        Vector3d grad = pair_gradient(c, rule, slot, master, other);
        for (int d = 0; d < 3; ++d)
          if (held[c.node(slot)] & (1u << d)) grad[d] = 0.0;
        const bool usable = c.mass[ContactNodes::flat(slot, master)] > 0.0 &&
                            c.mass[ContactNodes::flat(slot, other)] > 0.0 &&
                            grad.squaredNorm() > 0.0;
        c.pair_master[k] = static_cast<std::int8_t>(usable ? master : -1);
        // Eq 3.30: sum_p m_p grad N_I(x_p) points from the body's points towards the node, so
        // at a surface node it is the master body's outward unit normal.
        const Vector3d n = usable ? grad.normalized() : Vector3d::Zero();
        for (int d = 0; d < 3; ++d) c.pair_normal[d][k] = n[d];
        c.master_surface[k] = -std::numeric_limits<double>::infinity();
        c.other_surface[k] = std::numeric_limits<double>::infinity();
        c.pair_touching[k] = 0;
        c.pair_bonded_sides[k] = 0;
        c.pair_bond_forms[k] = 0;
        c.bond_weight[k] = c.bond_strength[k] = c.bond_share[k] = c.bond_damage[k] = 0.0;
        c.side_weight[0][k] = c.side_weight[1][k] = c.bond_area[k] = c.opened_damage[k] = 0.0;
      }
  }
}

double nodal_bond(const ContactNodes& c, const std::vector<double>& bond_sum, std::int32_t slot,
                  int e1, int e2, case_file::NodalAverage average) {
  double sum = 0.0;
  for (const int e : {e1, e2}) {
    const std::size_t f = ContactNodes::flat(slot, e);
    if (c.surface_count[f] == 0) continue;
    sum += bond_sum[f] /
           (average == case_file::NodalAverage::Count ? c.surface_count[f] : c.surface_weight[f]);
  }
  return 0.5 * sum;
}

namespace {

// The bond force at a pair's node under the debonding law (bonding/cohesive_law.hpp): the full
// sticking correction `stick` (eq 3.31 times dt, on the master, whose outward normal is n) while
// the traction it takes, stick / (dt A), is within what the bond's points carry there; past it,
// that traction, the normal part kept where it presses the bodies together. The opening the
// bodies' relative velocity then makes over the step damages the bond (opened_damage).
Vector3d cohesive_bond_force(ContactNodes& c, std::size_t k, const ContactRule& rule, double dt,
                             const Vector3d& stick, const Vector3d& n, const Vector3d& pm,
                             const Vector3d& ps, double mm, double ms) {
  const bonding::CohesiveLaw& law = rule.debond;
  const double w = c.bond_weight[k];
  const double strength = c.bond_strength[k] / w;
  const double damage = c.bond_damage[k] / w;
  const double capacity = bonding::traction_capacity(strength, damage);
  const double carried =
      bonding::effective_traction(stick / (dt * c.bond_area[k]), n, law.shear_ratio);
  if (carried <= capacity) return stick;
  const double scale = capacity / carried;
  const double normal = stick.dot(n);
  const Vector3d dp =
      normal < 0.0 ? Vector3d(normal * n + scale * (stick - normal * n)) : Vector3d(scale * stick);
  // The other body's displacement relative to the master's once dp acts, over the step.
  const Vector3d opening = dt * ((ps - dp) / ms - (pm + dp) / mm);
  const double energy = law.fracture_energy * c.bond_share[k] / w;
  const double opened =
      strength > 0.0 && energy > 0.0
          ? bonding::damage_increment(bonding::effective_opening(opening, n, law.shear_ratio),
                                      strength, energy)
          : 1.0;  // a bond that carries nothing lets go at once
  c.opened_damage[k] = opened;
  return dp;
}

// Sweeps over the pairs of a node that three or more bodies share, at most (resolve_contact).
constexpr int kMaxSweeps = 100;
// A sweep whose largest correction is below this share of the node's momentum ends them.
constexpr double kSweepTolerance = 1e-12;

// One pair's correction at its node (resolve_contact). On the first sweep it decides the pair's
// contact and bond (pair_touching, pair_bond_forms); later sweeps keep those decisions and
// correct again only what the other pairs' corrections undid: a bonded pair's common velocity,
// a touching pair's approach along its normal. A cohesive bond (the debonding law) acts on the
// first sweep only, so that its traction limit holds. Returns |dp|.
double resolve_pair(ContactNodes& c, const ContactRule& rule, double dt, int bodies,
                    std::vector<std::array<double, 3>>& impulse, std::int32_t slot, int e1, int e2,
                    bool first_sweep) {
  const std::size_t k = ContactNodes::pair(slot, e1, e2);
  if (c.pair_master[k] < 0) return 0.0;
  const int em = c.pair_master[k], es = em == e1 ? e2 : e1;
  const std::size_t fm = ContactNodes::flat(slot, em), fs = ContactNodes::flat(slot, es);
  const int bm = c.body(slot, em), bs = c.body(slot, es);
  const double mm = c.mass[fm], ms = c.mass[fs];
  const Vector3d n = load(c.pair_normal, k);
  const Vector3d pm = load(c.momentum, fm), ps = load(c.momentum, fs);
  // Eq 3.29: the bodies approach when (m_s p_m - m_m p_s) . n > 0.
  const bool approaching = (ms * pm - mm * ps).dot(n) > 0.0;
  // The gap check: the surfaces meet by the end of the step, moving at the nodal velocities.
  const bool touching =
      rule.gap_check
          ? c.other_surface[k] - c.master_surface[k] + dt * (ps / ms - pm / mm).dot(n) <= 0.0
          : approaching;
  if (first_sweep) {
    c.pair_touching[k] = touching;
    // An activated pair bonds where it touches; without activation, where eq 4.7 says.
    c.pair_bond_forms[k] =
        rule.bonding && rule.pair_may_bond(bm, bs, bodies) &&
        (rule.activation ? touching : bond_forms(nodal_bond(c, slot, e1, e2, rule.nodal_average)));
  }
  const bool bonded = c.pair_bond_forms[k] || (rule.bonding && bond_holds(c.pair_bonded_sides[k]));
  if (!bonded && !(approaching && touching)) return 0.0;
  // Eq 3.31 times dt: the momentum change that gives both bodies the common velocity.
  const Vector3d stick = (mm * ps - ms * pm) / (mm + ms);
  const double normal = stick.dot(n);
  // (A body with next to no mass at the node, below the floor, has no velocity there to
  // open the bond with: its share of the bond passes elsewhere.)
  const bool cohesive =
      bonded && rule.debond.enabled && c.bond_area[k] > 0.0 && std::min(mm, ms) > rule.mass_floor;
  if (cohesive && !first_sweep) return 0.0;
  Vector3d dp = cohesive ? cohesive_bond_force(c, k, rule, dt, stick, n, pm, ps, mm, ms)
                : bonded ? stick
                         : Vector3d(normal * n);
  if (!bonded && rule.friction > 0.0) {
    const Vector3d tangential = stick - dp;
    const double t = tangential.norm(), limit = rule.friction * std::abs(normal);
    dp += t > limit ? tangential * (limit / t) : tangential;
  }
  add_to(c.momentum, fm, dp);
  add_to(c.momentum, fs, -dp);
  add_to(c.force, fm, dp / dt);
  add_to(c.force, fs, -dp / dt);
  add_to(c.correction, fm, dp);
  add_to(c.correction, fs, -dp);
  for (int d = 0; d < 3; ++d) {
    impulse[bm * bodies + bs][d] += dp[d];
    impulse[bs * bodies + bm][d] -= dp[d];
  }
  return dp.norm();
}

// The sum of |p| over the bodies at a node: the scale of its corrections.
double momentum_scale(const ContactNodes& c, std::int32_t slot) {
  double scale = 0.0;
  for (int e = 0; e < c.body_count(slot); ++e)
    scale += load(c.momentum, ContactNodes::flat(slot, e)).norm();
  return scale;
}

}  // namespace

void resolve_contact(ContactNodes& c, const ContactRule& rule, double dt, int bodies,
                     std::vector<std::array<double, 3>>& impulse) {
  for (std::size_t s = 0; s < c.size(); ++s) {
    const auto slot = static_cast<std::int32_t>(s);
    const int count = c.body_count(slot);
    // Where three or more bodies meet, a pair's correction changes a body another pair has
    // already corrected: one sweep left bonded bodies at different velocities and touching ones
    // approaching, and a junction of three bodies' contacts squeezed its material step after
    // step (docs/validation/multi-particle.md). So the sweeps repeat, each pair projecting the
    // bodies onto its own condition in turn (projected Gauss-Seidel), until the corrections
    // vanish. Two bodies need one sweep: it meets their one condition exactly.
    const double tolerance = count > 2 ? kSweepTolerance * momentum_scale(c, slot) : 0.0;
    for (int sweep = 0; sweep < (count > 2 ? kMaxSweeps : 1); ++sweep) {
      double largest = 0.0;
      for (int e1 = 0; e1 < count; ++e1)
        for (int e2 = e1 + 1; e2 < count; ++e2)
          largest = std::max(largest,
                             resolve_pair(c, rule, dt, bodies, impulse, slot, e1, e2, sweep == 0));
      if (largest <= tolerance) break;
    }
  }
}

}  // namespace coldspray::mpm
