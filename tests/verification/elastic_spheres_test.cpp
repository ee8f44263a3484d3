// Two elastic spheres colliding head-on: momentum conserved to 1e-10 relative and at least 94 %
// of the kinetic energy carried away as rigid-body motion once they separate (94.9 % measured at
// these 0.25 um cells, 97.9 % at 0.125 um: the loss is the grid's, and halves with the cell, see
// the case file); contact.csv holds the pair's force, equal to each body's total contact force
// in history.csv. In peridynamics (examples/verification/pd-elastic-spheres.yaml) at least 90 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

// Runs the case and checks the head-on collision: momentum to 1e-10 of either sphere's initial
// momentum (each sphere starts at 50 m/s), at least `recovered` of the kinetic energy back as
// rigid-body motion, the energy budget within 1 %.
CaseRun expect_elastic_head_on(const char* name, double recovered) {
  const CaseRun run = run_verification_case(name);
  const auto& upper = run.summary.bodies.at(0);
  const auto& lower = run.summary.bodies.at(1);
  const double total = upper.mass * upper.velocity[2] + lower.mass * lower.velocity[2];
  const double momentum_error = std::abs(total) / (upper.mass * 50.0);
  const double rebound = 0.5 * (upper.velocity[2] - lower.velocity[2]);
  std::printf(
      "%s: momentum error %.2e, rebound speed %.3f m/s of 50, rigid-body kinetic energy "
      "recovered %.1f %%, energy budget error %.2e\n",
      name, momentum_error, rebound, 100.0 * rebound * rebound / 2500.0,
      run.summary.energy_relative_error());
  EXPECT_LT(momentum_error, 1e-10);
  EXPECT_GT(rebound * rebound / 2500.0, recovered);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
  return run;
}

// Peridynamics (docs/pd.md): 93.8 % measured at 0.5 um spacing.
TEST(Verification, PeridynamicElasticSpheresConserveMomentum) {
  expect_elastic_head_on("pd-elastic-spheres", 0.90);
}

TEST(Verification, ElasticSpheresConserveMomentum) {
  const CaseRun run = expect_elastic_head_on("elastic-spheres", 0.94);

  // With two bodies, the force on `upper` from `lower` is upper's whole contact force, and
  // lower feels the opposite.
  std::map<double, double> pair_fz;  // time -> fz on upper from lower
  std::ifstream csv(run.out_dir + "/contact.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "time,body,other,fx,fy,fz");
  while (std::getline(csv, line)) {
    std::stringstream row(line);
    std::string time, body, other, fx, fy, fz;
    std::getline(row, time, ',');
    std::getline(row, body, ',');
    std::getline(row, other, ',');
    std::getline(row, fx, ',');
    std::getline(row, fy, ',');
    std::getline(row, fz, ',');
    EXPECT_EQ(body + "/" + other, "upper/lower");
    pair_fz[std::stod(time)] = std::stod(fz);
  }
  const Table h = run.history();
  const auto t = h.values("time"), upper_fz = h.values("upper.contact_fz"),
             lower_fz = h.values("lower.contact_fz");
  std::size_t touching = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto it = pair_fz.find(t[i]);
    const double fz = it == pair_fz.end() ? 0.0 : it->second;
    touching += fz != 0.0;
    EXPECT_NEAR(upper_fz[i], fz, 1e-9 * std::abs(fz) + 1e-12);
    EXPECT_NEAR(lower_fz[i], -fz, 1e-9 * std::abs(fz) + 1e-12);
  }
  EXPECT_GT(touching, 5u);
}

}  // namespace
}  // namespace coldspray::verification
