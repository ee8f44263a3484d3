// The debonding law (bonding/cohesive_law.hpp; docs/bonding.md, "Debonding"):
// - its traction-separation curve, walked in the steps the contact takes, gives back the
//   fracture energy (hand calculation: the area of the triangle sigma_c delta_c / 2 = G_c);
// - its mixed-mode measures (Ortiz and Pandolfi) by hand;
// - with a strength no traction reaches the law does nothing: the run is bit for bit the one
//   without it (debond.law: none).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bodies/grip.hpp"
#include "bonding/cohesive_law.hpp"
#include "case/load.hpp"
#include "core/error.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

TEST(CohesiveLaw, TractionSeparationCurveIntegratesToTheFractureEnergy) {
  // Opened in n equal steps, each carrying the traction of the damage at its start (as
  // resolve_contact does): the left Riemann sum of sigma_c (1 - delta / delta_c), which exceeds
  // the triangle's area G_c by sigma_c delta_c / (2 n) = G_c / n.
  const double sigma = 150e6, G = 400.0, delta_c = 2.0 * G / sigma;
  for (const int n : {10, 1000}) {
    double damage = 0.0, work = 0.0;
    const double step = delta_c / n;
    while (damage < 1.0 - 1e-12) {
      work += bonding::traction_capacity(sigma, damage) * step;
      damage += bonding::damage_increment(step, sigma, G);
    }
    EXPECT_NEAR(work, G * (1.0 + 1.0 / n), 1e-9 * G) << n << " steps";
  }
}

TEST(CohesiveLaw, MixedModeMeasures) {
  const Eigen::Vector3d n(0.0, 0.0, 1.0);
  // Tension counts, compression does not; shear counts divided by beta.
  EXPECT_DOUBLE_EQ(bonding::effective_traction({0.0, 0.0, 3.0}, n, 1.0), 3.0);
  EXPECT_DOUBLE_EQ(bonding::effective_traction({0.0, 0.0, -3.0}, n, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(bonding::effective_traction({3.0, 0.0, 4.0}, n, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(bonding::effective_traction({4.0, 0.0, -9.0}, n, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(bonding::effective_opening({3.0, 0.0, 4.0}, n, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(bonding::effective_opening({1.0, 0.0, -2.0}, n, 2.0), 2.0);
}

case_file::Case discs(const std::string& geometry,
                      const std::vector<case_file::Override>& more = {}) {
  std::vector<case_file::Override> o = {{"solver.geometry", geometry}};
  o.insert(o.end(), more.begin(), more.end());
  return case_file::load_case(std::string(COLDSPRAY_TEST_DATA) + "/cases/bonded-discs.yaml", o);
}

// Bonds the discs' facing layers to each other, at D_bond = 1.
void bond_facing_layers(State& s) {
  Points& P = s.points;
  const double spacing = s.bodies[0].spacing;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const bool upper = P.body[p] == 0;
    const double z = P.position[2][p];
    if (!P.surface[p] || (upper ? z > spacing : z < -spacing)) continue;
    P.bond[p] = 1.0;
    P.bonded_to[p] = upper ? 2 : 1;  // 1 + the other body
  }
}

std::size_t bonded_points(const State& s) {
  std::size_t n = 0;
  for (const auto b : s.points.bonded_to) n += b != 0;
  return n;
}

TEST(Debonding, AStrengthNothingReachesLeavesTheRunAsWithoutTheLaw) {
  auto run = [](const std::string& law) {
    const case_file::Case c = discs("axisymmetric", {{"bodies.upper.velocity", "[0, 0, 5 m/s]"},
                                                     {"bonding.debond.law", law},
                                                     {"bonding.debond.strength", "1e30 Pa"}});
    State s = build_state(c);
    bond_facing_layers(s);
    for (int k = 0; k < 300; ++k) {
      s.dt = stable_time_step(s, c.solver.cfl);
      step(s);
    }
    return s;
  };
  const State with = run("cohesive"), without = run("none");
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(with.points.position[d], without.points.position[d]);
    EXPECT_EQ(with.points.velocity[d], without.points.velocity[d]);
  }
  EXPECT_EQ(with.points.bonded_to, without.points.bonded_to);
  EXPECT_GT(bonded_points(with), 0u);
}

TEST(Grip, RefusesToTakeInAnotherBodysPoints) {
  const case_file::Case c = discs("3d");
  State s = build_state(c);
  const case_file::Grip grip{"upper", 1.0, {0.0, 0.0, 1.0}, case_file::Vec3::Zero(), 0.0};
  bodies::prepare_grip(s, grip);
  bodies::take_grip(s, grip);  // the discs are apart: fine
  std::size_t gripped = 0;
  for (const auto g : s.gripped) gripped += g;
  EXPECT_EQ(gripped, s.bodies[0].end - s.bodies[0].begin);
  // A point of the lower disc among the upper one's: the grip would drag it along.
  s.points.position[2][s.bodies[1].begin] = 0.75e-6;
  try {
    bodies::take_grip(s, grip);
    FAIL() << "took the grip";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "grip.fraction");
  }
}

}  // namespace
}  // namespace coldspray::mpm
