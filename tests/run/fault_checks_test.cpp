// The fault checks (run/fault_checks.hpp; docs/reliability.md, "Faults that cannot pass as ok"):
// each rule passes a valid state and stops a broken one, issue 24's reproducer among them.
#include "run/fault_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"
#include "metrics/energy.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::run {
namespace {

case_file::Case bonding_impact(const std::vector<case_file::Override>& overrides = {}) {
  return case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/bonding-impact.yaml", overrides);
}

// Issue 24's reproducer: a grid cell far coarser than the bodies makes the absorbing faces
// unstable; the substrate's velocity flips sign and grows each step.
case_file::Case reproducer() {
  return bonding_impact({{"grid.cell_size", "20 um"}, {"solver.end_time", "10 ns"}});
}

// The message of the fault the checks find in `s`, or "" if none.
std::string fault_in(const bodies::Bodies& s, double initial_total) {
  try {
    FaultChecks(initial_total).check(s, metrics::energy_budget(s));
  } catch (const RunFault& fault) {
    return fault.what();
  }
  return "";
}

// The sum of a per-point array over a body's points (its mass, its volume).
double sum_over(const std::vector<double>& values, const bodies::BodyRange& body) {
  double sum = 0.0;
  for (std::size_t p = body.begin; p < body.end; ++p) sum += values[p];
  return sum;
}

struct Started {
  mpm::State s;
  double initial_total;
};

Started started(const case_file::Case& c, int steps) {
  Started r{mpm::build_state(c), 0.0};
  r.initial_total = metrics::energy_budget(r.s).total();
  for (int n = 0; n < steps; ++n) {
    r.s.dt = mpm::stable_time_step(r.s, c.solver.cfl);
    mpm::step(r.s);
  }
  return r;
}

TEST(FaultChecks, AValidImpactPassesThroughout) {
  const case_file::Case c = bonding_impact({{"solver.end_time", "5 ns"}});
  Started r = started(c, 0);
  for (int n = 0; n < 200; ++n) {
    ASSERT_EQ(fault_in(r.s, r.initial_total), "") << "step " << r.s.step;
    r.s.dt = mpm::stable_time_step(r.s, c.solver.cfl);
    mpm::step(r.s);
  }
}

// At step 10, the reproducer's first check, the substrate's mean motion carries 3.1 times the
// initial total energy while the total, lowered by a negative absorbed energy, has not grown.
TEST(FaultChecks, TheReproducersSubstrateIsFasterThanTheEnergyAllows) {
  const Started r = started(reproducer(), static_cast<int>(kFaultCheckStride));
  const metrics::EnergyBudget e = metrics::energy_budget(r.s);
  EXPECT_LT(e.total(), (1.0 + kEnergyGrowthLimit) * r.initial_total);  // the old check's blind spot
  const std::string fault = fault_in(r.s, r.initial_total);
  EXPECT_NE(fault.find("body 'substrate': mean velocity"), std::string::npos) << fault;
  EXPECT_NE(fault.find("faster than"), std::string::npos) << fault;
}

// The same state with every point stopped: no body moves, and the dashpots' ledger alone shows
// that they gave energy back.
TEST(FaultChecks, TheReproducersAbsorbingFacesGaveEnergyBack) {
  Started r = started(reproducer(), static_cast<int>(kFaultCheckStride));
  for (auto& v : r.s.points.velocity) std::fill(v.begin(), v.end(), 0.0);
  const std::string fault = fault_in(r.s, r.initial_total);
  EXPECT_NE(fault.find("the absorbing faces gave back"), std::string::npos) << fault;
}

TEST(FaultChecks, ANegativeAbsorbedEnergyBeyondTheToleranceIsAFault) {
  Started r = started(bonding_impact(), 0);
  ASSERT_FALSE(r.s.absorbing.empty());
  r.s.absorbing.front().absorbed = -0.9 * kEnergyGrowthLimit * r.initial_total;
  EXPECT_EQ(fault_in(r.s, r.initial_total), "");
  r.s.absorbing.front().absorbed = -1.1 * kEnergyGrowthLimit * r.initial_total;
  EXPECT_NE(fault_in(r.s, r.initial_total).find("the absorbing faces gave back"),
            std::string::npos);
}

// Internal energy from nowhere, 0.3 times the initial total spread over the particle, with every
// velocity as it was: the total grows past 1.2 times the initial while no body moves faster.
TEST(FaultChecks, TotalEnergyGrowthIsAFault) {
  Started r = started(bonding_impact(), 0);
  bodies::Points& P = r.s.points;
  const bodies::BodyRange& particle = r.s.bodies[0];
  const double volume = sum_over(P.volume0, particle);
  for (const double share : {0.1, 0.3}) {
    for (std::size_t p = particle.begin; p < particle.end; ++p)
      P.energy[p] = share * r.initial_total / volume;
    const std::string fault = fault_in(r.s, r.initial_total);
    if (share < kEnergyGrowthLimit)
      EXPECT_EQ(fault, "");
    else
      EXPECT_NE(fault.find("total energy grew"), std::string::npos) << fault;
  }
}

// The bound on a body's mean velocity, when the ledger hides the energy (a contact term as
// negative as the substrate's motion is energetic): just under it passes, just over it faults.
TEST(FaultChecks, ABodyFasterThanTheEnergyAllowsIsAFaultWhateverTheLedger) {
  Started r = started(bonding_impact(), 0);
  bodies::Points& P = r.s.points;
  const bodies::BodyRange& substrate = r.s.bodies[1];
  ASSERT_EQ(substrate.name, "substrate");
  const double mass = sum_over(P.mass, substrate);
  const double bound = std::sqrt(2.0 * (1.0 + kEnergyGrowthLimit) * r.initial_total / mass);
  for (const double factor : {0.99, 1.01}) {
    for (std::size_t p = substrate.begin; p < substrate.end; ++p) {
      P.velocity[2][p] = factor * bound;
      P.contact_work[p] = 0.5 * P.mass[p] * P.velocity[2][p] * P.velocity[2][p];
    }
    const std::string fault = fault_in(r.s, r.initial_total);
    if (factor < 1.0)
      EXPECT_EQ(fault, "");
    else
      EXPECT_NE(fault.find("body 'substrate': mean velocity"), std::string::npos) << fault;
  }
}

// An adhesive contact (the PD paper's model 1) turns its well's depth into motion: what its
// attraction released (the budget's contact entry below zero) is added to the energy a body's
// mean motion may carry, and only then.
TEST(FaultChecks, AnAdhesiveWellsReleaseMayDriveABody) {
  Started r = started(bonding_impact(), 0);
  bodies::Points& P = r.s.points;
  const bodies::BodyRange& substrate = r.s.bodies[1];
  const double mass = sum_over(P.mass, substrate);
  const double bound = std::sqrt(2.0 * (1.0 + kEnergyGrowthLimit) * r.initial_total / mass);
  for (std::size_t p = substrate.begin; p < substrate.end; ++p) {
    P.velocity[2][p] = 1.5 * bound;
    P.contact_work[p] = 0.5 * P.mass[p] * P.velocity[2][p] * P.velocity[2][p];
  }
  const metrics::EnergyBudget e = metrics::energy_budget(r.s);
  ASSERT_LT(e.contact, 0.0);
  EXPECT_NO_THROW(FaultChecks(r.initial_total, /*adhesive=*/true).check(r.s, e));
  EXPECT_NE(fault_in(r.s, r.initial_total).find("body 'substrate': mean velocity"),
            std::string::npos);
}

TEST(FaultChecks, ANonFiniteTemperatureIsAFaultNamingThePoint) {
  Started r = started(bonding_impact(), 0);
  const std::size_t p = r.s.bodies[0].begin + 7;
  r.s.points.temperature[p] = std::numeric_limits<double>::infinity();
  const std::string fault = fault_in(r.s, r.initial_total);
  EXPECT_NE(fault.find("body 'particle', point"), std::string::npos) << fault;
  EXPECT_NE(fault.find("temperature inf K"), std::string::npos) << fault;
}

TEST(FaultChecks, ANonFiniteEnergyIsAFault) {
  Started r = started(bonding_impact(), 0);
  r.s.points.energy[3] = std::numeric_limits<double>::quiet_NaN();
  const std::string fault = fault_in(r.s, r.initial_total);
  EXPECT_NE(fault.find("the energy budget is not finite"), std::string::npos) << fault;
}

}  // namespace
}  // namespace coldspray::run
