// The direct bonding model on a small impact (examples/verification/bonding-impact.yaml): without
// bonding the particle rebounds; with a tiny critical adhesion energy every contacted point bonds
// and the particle stays; the bond force, like the contact force, conserves momentum. The verdict
// (docs/bonding.md, "The verdict") reads each right, its mean separation speed is that of the
// history's v_rest columns over the last 20 ns, and a run whose window still holds the impact is
// extended by a window.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

// The mean over the history's rows in [t0, t1] of particle.v_rest - substrate.v_rest: the
// separation velocity of a particle that came down, every 0.5 ns (the verdict samples it every
// 0.1 ns, from its own pass over the points).
double history_separation(const CaseRun& run, double t0, double t1) {
  const Table h = run.history();
  const std::vector<double> t = h.values("time"), particle = h.values("particle.v_rest"),
                            substrate = h.values("substrate.v_rest");
  std::vector<double> separation(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) separation[i] = particle[i] - substrate[i];
  return mean_over(t, separation, t0, t1);
}

TEST(Verification, WithoutBondingTheParticleRebounds) {
  const CaseRun run = run_verification_case("bonding-impact", {{"bonding.model", "none"}});
  const auto& particle = run.summary.bodies.at(0);
  const auto& m = particle.impact;
  ASSERT_TRUE(particle.verdict);
  const metrics::Verdict& v = *particle.verdict;
  std::printf("no bonding: cor %.4f, v_rest %.2f m/s, pbcp %.1f %%; %s, separation %.3f m/s\n",
              m.cor, m.v_rest, m.pbcp, std::string(metrics::outcome_name(v.outcome)).c_str(),
              v.separation_speed);
  EXPECT_GT(m.cor, 0.02);
  EXPECT_EQ(m.pbcp, 0.0);
  EXPECT_EQ(v.outcome, metrics::Outcome::Rebounded);
  EXPECT_NEAR(v.separation_speed, history_separation(run, 20e-9, 40e-9), 0.1);
  EXPECT_NEAR(v.margin, 2.0 - v.separation_speed, 1e-12);
  EXPECT_LT(v.margin, -10.0);  // it leaves at tens of m/s
  EXPECT_EQ(run.summary.extensions, 0);
}

// Bonding's activation (docs/bonding.md, "Activation"). Before a pair is activated no bond
// forms, whatever the law's D_bond (here G_c = 1 J/m^2, which bonds every contacted point at
// once): the impact moves as without a bonding model, to the bit.
TEST(Verification, BeforeItsActivationAnImpactMovesAsWithoutBonding) {
  const CaseRun off = run_verification_case("bonding-impact", {{"bonding.model", "none"}});
  const CaseRun held = run_verification_case(
      "bonding-impact",
      {{"bonding.critical_energy", "1 J/m^2"}, {"bonding.critical_penetration", "0.99"}});
  const auto& m = held.summary.bodies.at(0).impact;
  EXPECT_GT(m.pbcp, 50.0);  // the law ran: its D_bond reached 1 over most of the contact
  EXPECT_EQ(m.bonded_area, 0.0);
  EXPECT_EQ(held.summary.bodies.at(0).verdict->outcome, metrics::Outcome::Rebounded);
  const Table a = off.history(), b = held.history();
  for (const char* column : {"time", "kinetic", "elastic", "plastic_work", "particle.vz",
                             "substrate.vz", "particle.penetration"})
    EXPECT_EQ(a.values(column), b.values(column)) << column;
}

// Unbonded, the impact penetrates p (its summary's largest penetration): with the critical share
// just above p the pair is never activated and the particle rebounds with no bond; just below, it
// is activated before the compression ends and stays, bonded.
TEST(Verification, APairBondsOnceItsImpactPenetratesTheCriticalShare) {
  const CaseRun first = run_verification_case(
      "bonding-impact", {{"bonding.critical_penetration", "0.99"}, {"solver.end_time", "20 ns"}});
  const double p = first.summary.bodies.at(0).impact.penetration;
  std::printf("penetration %.5f, compression ended at %.2f ns\n", p,
              first.summary.bodies.at(0).impact.penetration_peak_time * 1e9);
  ASSERT_GT(p, 0.2);
  ASSERT_LT(p, 0.6);
  for (const double factor : {1.02, 0.98}) {
    const CaseRun run = run_verification_case(
        "bonding-impact", {{"bonding.critical_energy", "1 J/m^2"},
                           {"bonding.critical_penetration", std::to_string(factor * p)}});
    const auto& particle = run.summary.bodies.at(0);
    if (factor > 1.0)  // never activated: the unbonded impact
      EXPECT_EQ(particle.impact.penetration, p);
    else  // bonded from just before the compression ended
      EXPECT_NEAR(particle.impact.penetration, p, 0.01 * p);
    EXPECT_EQ(particle.verdict->outcome,
              factor > 1.0 ? metrics::Outcome::Rebounded : metrics::Outcome::Bonded)
        << factor;
    EXPECT_EQ(particle.impact.bonded_area > 0.0, factor < 1.0) << factor;
  }
}

// Run for 20 ns, the last 20 ns hold the impact itself (in at -800 m/s, then stopped): undecided,
// so the run goes on one window, to 40 ns, where the particle, bonded, rings with the small
// substrate (its absorbing faces are close), and the verdict reads it bonded.
TEST(Verification, WithATinyAdhesionEnergyTheParticleBondsAfterAnExtension) {
  const CaseRun run = run_verification_case(
      "bonding-impact", {{"bonding.critical_energy", "1 J/m^2"}, {"solver.end_time", "20 ns"}});
  const auto& particle = run.summary.bodies.at(0);
  const auto& m = particle.impact;
  ASSERT_TRUE(particle.verdict);
  const metrics::Verdict& v = *particle.verdict;
  std::printf(
      "G_c = 1 J/m^2: cor %.4f, v_rest %.2f m/s, pbcp %.1f %%, abp %.0f; %s at %.1f ns, "
      "separation %.3f m/s, halves %.3f m/s apart\n",
      m.cor, m.v_rest, m.pbcp, m.abp, std::string(metrics::outcome_name(v.outcome)).c_str(),
      run.summary.time * 1e9, v.separation_speed, v.settling);
  EXPECT_LT(std::abs(m.cor), 0.01);
  EXPECT_EQ(m.pbcp, 100.0);
  EXPECT_EQ(run.summary.extensions, 1);
  EXPECT_NEAR(run.summary.time, 40e-9, 1e-18);
  EXPECT_EQ(v.outcome, metrics::Outcome::Bonded);
  EXPECT_NEAR(v.separation_speed, history_separation(run, 20e-9, 40e-9), 0.1);
  EXPECT_NEAR(v.margin, 2.0 - v.separation_speed, 1e-12);
  EXPECT_GT(v.margin, 0.0);
}

// The verdict's extension is held off (verdict_extensions 0): without absorbing faces the
// substrate's waves would carry its points off the grid soon after 20 ns.
TEST(Verification, TheBondForceConservesMomentum) {
  const CaseRun run =
      run_verification_case("bonding-impact", {{"bonding.critical_energy", "1 J/m^2"},
                                               {"bodies.substrate.absorbing", "[]"},
                                               {"solver.end_time", "20 ns"},
                                               {"metrics.verdict_extensions", "0"}});
  const auto& particle = run.summary.bodies.at(0);
  const auto& substrate = run.summary.bodies.at(1);
  const double initial = particle.mass * 800.0;
  const double total =
      particle.mass * particle.velocity[2] + substrate.mass * substrate.velocity[2];
  std::printf("bonded, no absorbing faces: momentum error %.2e, pbcp %.1f %%\n",
              std::abs(total + initial) / initial, particle.impact.pbcp);
  EXPECT_GT(particle.impact.pbcp, 50.0);
  EXPECT_LT(std::abs(total + initial) / initial, 1e-10);
  ASSERT_TRUE(particle.verdict);
  EXPECT_EQ(particle.verdict->outcome, metrics::Outcome::Undecided);  // and reported so
}

}  // namespace
}  // namespace coldspray::verification
