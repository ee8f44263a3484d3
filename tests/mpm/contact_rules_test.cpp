// The contact normal rules with three bodies at one node (mpm/contact.hpp): every rule's
// corrections conserve the node's momentum, and `average-gradient` gives each pair the same
// normal and the same corrections whichever way the bodies are numbered. The pairs' corrections
// repeat until they agree: three bonded bodies leave with one velocity, and no touching pair is
// left approaching.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mpm/contact.hpp"

namespace coldspray::mpm {
namespace {

using Eigen::Vector3d;

// Two particles above a substrate at one node: `left` (points up and to the left of the node,
// so its mass gradient points down and right), `right` (mirror image, a little heavier), and
// `substrate` below; the particles move down towards it and towards each other.
struct Body {
  double mass;
  Vector3d momentum, gradient;
};
const std::array<Body, 3> kBodies{{
    {1.0, Vector3d(0.3, 0.0, -1.0), Vector3d(1.0, 0.0, -1.2)},    // left
    {1.3, Vector3d(-0.2, 0.0, -1.1), Vector3d(-0.9, 0.0, -1.0)},  // right
    {4.0, Vector3d(0.0, 0.0, 0.0), Vector3d(0.1, 0.0, 2.0)},      // substrate
}};

// The node after the rule's normals and corrections, with the bodies numbered by `order`
// (order[k]: the number of body k), each pair bonded on both sides if `bonded`; `other_pairs` is
// the rule between the particles under body:substrate. Its one slot is 0.
ContactNodes resolved(
    case_file::ContactNormal normal, std::array<int, 3> order, bool bonded,
    case_file::ContactNormal other_pairs = case_file::ContactNormal::MaxGradient) {
  ContactNodes c;
  const std::int32_t slot = c.add(0);
  for (int k = 0; k < 3; ++k) {
    const std::size_t f = ContactNodes::flat(slot, c.entry(slot, order[k]));
    c.mass[f] = kBodies[k].mass;
    for (int d = 0; d < 3; ++d) {
      c.momentum[d][f] = kBodies[k].momentum[d];
      c.mass_gradient[d][f] = kBodies[k].gradient[d];
    }
  }
  ContactRule rule;
  rule.normal = normal;
  rule.normal_body = order[2];  // body:substrate
  rule.other_pairs = other_pairs;
  rule.reference_density = {2700.0, 2700.0, 2700.0};
  rule.gap_check = false;  // the approach test alone: the surfaces are not gathered here
  ContactResult result;
  result.gradient_weight.assign(9, 0.0);
  result.master.assign(9, 0);
  const std::vector<std::uint8_t> held(1, 0);
  choose_contact_normals(c, rule, held, 3, result);
  if (bonded) {  // bonds kept on both sides of every pair (ContactNodes::pair_bonded_sides)
    rule.bonding = true;
    for (int e1 = 0; e1 < 3; ++e1)
      for (int e2 = e1 + 1; e2 < 3; ++e2)
        c.pair_bonded_sides[ContactNodes::pair(slot, e1, e2)] =
            ContactNodes::kLowerSide | ContactNodes::kHigherSide;
  }
  std::vector<std::array<double, 3>> impulse(9, {0.0, 0.0, 0.0});
  resolve_contact(c, rule, 1e-9, 3, impulse);
  return c;
}

// Each body's momentum after the corrections, by body (not by number).
std::array<Vector3d, 3> corrected(
    case_file::ContactNormal normal, std::array<int, 3> order, bool bonded = false,
    case_file::ContactNormal other_pairs = case_file::ContactNormal::MaxGradient) {
  const ContactNodes c = resolved(normal, order, bonded, other_pairs);
  std::array<Vector3d, 3> out;
  for (int k = 0; k < 3; ++k) {
    const std::size_t f = ContactNodes::flat(0, c.find(0, order[k]));
    out[k] = Vector3d(c.momentum[0][f], c.momentum[1][f], c.momentum[2][f]);
  }
  return out;
}

TEST(ContactRules, EveryRuleConservesMomentumWithThreeBodiesAtANode) {
  Vector3d before = Vector3d::Zero();
  for (const Body& b : kBodies) before += b.momentum;
  for (const auto normal :
       {case_file::ContactNormal::MaxGradient, case_file::ContactNormal::AverageGradient,
        case_file::ContactNormal::HighestId, case_file::ContactNormal::Body}) {
    for (const auto other_pairs :
         {case_file::ContactNormal::MaxGradient, case_file::ContactNormal::AverageGradient}) {
      if (normal != case_file::ContactNormal::Body &&
          other_pairs != case_file::ContactNormal::MaxGradient)
        continue;  // other_pairs applies under body:NAME only
      const std::array<Vector3d, 3> after = corrected(normal, {0, 1, 2}, false, other_pairs);
      const Vector3d total = after[0] + after[1] + after[2];
      EXPECT_LT((total - before).norm(), 1e-15) << static_cast<int>(normal);
      // The particles were driven into the substrate: it takes momentum downwards.
      EXPECT_LT(after[2][2], -0.1) << static_cast<int>(normal);
    }
  }
}

// The pair's unit normal at the node's one slot, between the entries of bodies b1 and b2.
Vector3d pair_normal(const ContactNodes& c, int b1, int b2) {
  const int e1 = c.find(0, b1), e2 = c.find(0, b2);
  const std::size_t k = ContactNodes::pair(0, std::min(e1, e2), std::max(e1, e2));
  return Vector3d(c.pair_normal[0][k], c.pair_normal[1][k], c.pair_normal[2][k]);
}

// body:substrate with the average gradient between other pairs: each particle meets the
// substrate along the substrate's own normal, as under body:substrate alone, and the particles
// meet each other along their average gradient, as under average-gradient, whichever way the
// particles are numbered.
TEST(ContactRules, TheSubstratesNormalWithTheAverageGradientBetweenParticles) {
  using case_file::ContactNormal;
  const ContactNodes body = resolved(ContactNormal::Body, {0, 1, 2}, false);
  const ContactNodes average = resolved(ContactNormal::AverageGradient, {0, 1, 2}, false);
  for (const std::array<int, 3> order :
       {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{1, 0, 2}}) {
    const ContactNodes both =
        resolved(ContactNormal::Body, order, false, ContactNormal::AverageGradient);
    const int left = order[0], right = order[1], substrate = order[2];
    const Vector3d substrates = Vector3d(0.1, 0.0, 2.0).normalized();  // kBodies[2].gradient
    for (const int particle : {left, right}) {
      EXPECT_LT((pair_normal(both, particle, substrate) - substrates).norm(), 1e-15);
      EXPECT_LT((pair_normal(body, particle == left ? 0 : 1, 2) - substrates).norm(), 1e-15);
    }
    // Up to orientation (the master only orients it): the same line as the average gradient's.
    const Vector3d n = pair_normal(both, left, right), a = pair_normal(average, 0, 1);
    EXPECT_LT(std::min((n - a).norm(), (n + a).norm()), 1e-15);
    // Not the max-gradient's normal there, which body:substrate alone gives the particles.
    EXPECT_GT(std::min((n - pair_normal(body, 0, 1)).norm(), (n + pair_normal(body, 0, 1)).norm()),
              1e-3);
  }
}

TEST(ContactRules, TheAverageGradientDoesNotDependOnTheBodiesNumbering) {
  const std::array<Vector3d, 3> one =
      corrected(case_file::ContactNormal::AverageGradient, {0, 1, 2});
  for (const std::array<int, 3> order :
       {std::array<int, 3>{2, 0, 1}, std::array<int, 3>{1, 2, 0}}) {
    const std::array<Vector3d, 3> other =
        corrected(case_file::ContactNormal::AverageGradient, order);
    for (int k = 0; k < 3; ++k) EXPECT_LT((one[k] - other[k]).norm(), 1e-14) << k;
  }
  // The thesis' highest-id rule does: renumbered, the substrate gives way to a particle's normal.
  const std::array<Vector3d, 3> a = corrected(case_file::ContactNormal::HighestId, {0, 1, 2});
  const std::array<Vector3d, 3> b = corrected(case_file::ContactNormal::HighestId, {2, 0, 1});
  EXPECT_GT((a[2] - b[2]).norm(), 1e-3);
}

// One sweep of pairwise sticks left the three at three velocities (the last pair's correction
// moved a body the first had stuck), and the junction's material was squeezed step after step.
TEST(ContactRules, ThreeBondedBodiesLeaveTheNodeWithOneVelocity) {
  double mass = 0.0;
  Vector3d before = Vector3d::Zero();
  for (const Body& b : kBodies) {
    mass += b.mass;
    before += b.momentum;
  }
  const Vector3d common = before / mass;  // the node's centre-of-mass velocity
  for (const auto normal :
       {case_file::ContactNormal::AverageGradient, case_file::ContactNormal::HighestId}) {
    const std::array<Vector3d, 3> after = corrected(normal, {0, 1, 2}, /*bonded=*/true);
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((after[k] / kBodies[k].mass - common).norm(), 1e-11 * common.norm())
          << "body " << k << ", rule " << static_cast<int>(normal);
    EXPECT_LT((after[0] + after[1] + after[2] - before).norm(), 1e-14);
  }
}

// Frictionless: after the corrections no pair approaches along its normal (eq 3.29), to
// rounding.
TEST(ContactRules, NoPairOfThreeBodiesIsLeftApproaching) {
  for (const auto normal :
       {case_file::ContactNormal::AverageGradient, case_file::ContactNormal::HighestId,
        case_file::ContactNormal::MaxGradient}) {
    const ContactNodes c = resolved(normal, {0, 1, 2}, /*bonded=*/false);
    const std::int32_t slot = 0;
    for (int e1 = 0; e1 < 3; ++e1)
      for (int e2 = e1 + 1; e2 < 3; ++e2) {
        const std::size_t k = ContactNodes::pair(slot, e1, e2);
        ASSERT_GE(c.pair_master[k], 0);
        const int em = c.pair_master[k], es = em == e1 ? e2 : e1;
        const std::size_t fm = ContactNodes::flat(slot, em), fs = ContactNodes::flat(slot, es);
        const Vector3d n(c.pair_normal[0][k], c.pair_normal[1][k], c.pair_normal[2][k]);
        const Vector3d vm(c.momentum[0][fm], c.momentum[1][fm], c.momentum[2][fm]);
        const Vector3d vs(c.momentum[0][fs], c.momentum[1][fs], c.momentum[2][fs]);
        // (v_m - v_s) . n > 0 approaches: at most rounding left.
        EXPECT_LT((vm / c.mass[fm] - vs / c.mass[fs]).dot(n), 1e-12)
            << "pair " << e1 << "-" << e2 << ", rule " << static_cast<int>(normal);
      }
  }
}

}  // namespace
}  // namespace coldspray::mpm
