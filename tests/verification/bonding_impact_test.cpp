// The direct bonding model on a small impact (examples/verification/bonding-impact.yaml): without
// bonding the particle rebounds; with a tiny critical adhesion energy every contacted point bonds
// and the particle stays; the bond force, like the contact force, conserves momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, WithoutBondingTheParticleRebounds) {
  const CaseRun run = run_verification_case("bonding-impact", {{"bonding.model", "none"}});
  const auto& m = run.summary.bodies.at(0).impact;
  std::printf("no bonding: cor %.4f, v_rest %.2f m/s, pbcp %.1f %%\n", m.cor, m.v_rest, m.pbcp);
  EXPECT_GT(m.cor, 0.02);
  EXPECT_EQ(m.pbcp, 0.0);
  EXPECT_FALSE(m.bonded);
}

// The bonded particle rings with the small substrate at a few m/s (its absorbing faces are
// close), so the rest-speed tolerance is widened here; cor stays below 1 % of the impact speed.
TEST(Verification, WithATinyAdhesionEnergyTheParticleBonds) {
  const CaseRun run = run_verification_case(
      "bonding-impact",
      {{"bonding.critical_energy", "1 J/m^2"}, {"metrics.bonded_rest_speed", "5 m/s"}});
  const auto& m = run.summary.bodies.at(0).impact;
  std::printf("G_c = 1 J/m^2: cor %.4f, v_rest %.2f m/s, pbcp %.1f %%, abp %.0f\n", m.cor, m.v_rest,
              m.pbcp, m.abp);
  EXPECT_LT(std::abs(m.cor), 0.01);
  EXPECT_EQ(m.pbcp, 100.0);
  EXPECT_TRUE(m.bonded);
}

TEST(Verification, TheBondForceConservesMomentum) {
  const CaseRun run =
      run_verification_case("bonding-impact", {{"bonding.critical_energy", "1 J/m^2"},
                                               {"bodies.substrate.absorbing", "[]"},
                                               {"solver.end_time", "20 ns"}});
  const auto& particle = run.summary.bodies.at(0);
  const auto& substrate = run.summary.bodies.at(1);
  const double initial = particle.mass * 800.0;
  const double total =
      particle.mass * particle.velocity[2] + substrate.mass * substrate.velocity[2];
  std::printf("bonded, no absorbing faces: momentum error %.2e, pbcp %.1f %%\n",
              std::abs(total + initial) / initial, particle.impact.pbcp);
  EXPECT_GT(particle.impact.pbcp, 50.0);
  EXPECT_LT(std::abs(total + initial) / initial, 1e-10);
}

}  // namespace
}  // namespace coldspray::verification
