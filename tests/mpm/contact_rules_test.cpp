// The contact normal rules with three bodies at one node (mpm/contact.hpp): every rule's
// corrections conserve the node's momentum, and `average-gradient` gives each pair the same
// normal and the same corrections whichever way the bodies are numbered.
#include <gtest/gtest.h>

#include <Eigen/Core>
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

// Runs the rule with the bodies numbered by `order` (order[k]: the number of body k) and
// returns each body's momentum after the corrections, by body (not by number).
std::array<Vector3d, 3> corrected(case_file::ContactNormal normal, std::array<int, 3> order) {
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
  rule.reference_density = {2700.0, 2700.0, 2700.0};
  rule.gap_check = false;  // the approach test alone: the surfaces are not gathered here
  ContactResult result;
  result.gradient_weight.assign(9, 0.0);
  result.master.assign(9, 0);
  const std::vector<std::uint8_t> held(1, 0);
  choose_contact_normals(c, rule, held, 3, result);
  std::vector<std::array<double, 3>> impulse(9, {0.0, 0.0, 0.0});
  resolve_contact(c, rule, 1e-9, 3, impulse);
  std::array<Vector3d, 3> out;
  for (int k = 0; k < 3; ++k) {
    const std::size_t f = ContactNodes::flat(slot, c.find(slot, order[k]));
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
    const std::array<Vector3d, 3> after = corrected(normal, {0, 1, 2});
    const Vector3d total = after[0] + after[1] + after[2];
    EXPECT_LT((total - before).norm(), 1e-15) << static_cast<int>(normal);
    // The particles were driven into the substrate: it takes momentum downwards.
    EXPECT_LT(after[2][2], -0.1) << static_cast<int>(normal);
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

}  // namespace
}  // namespace coldspray::mpm
