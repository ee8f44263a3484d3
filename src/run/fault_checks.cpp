#include "run/fault_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bodies/describe_point.hpp"
#include "core/error.hpp"

namespace coldspray::run {

namespace {

// The first point (in index order, so the report does not depend on the threads) whose
// temperature is not finite: a specific heat that underflows the heating's division
// (dT = chi sigma_y d(eqps) / (rho C_p)) makes it inf while the energy budget, which counts
// internal energy and not temperature, stays finite.
void check_temperatures(const bodies::Bodies& s) {
  const bodies::Points& P = s.points;
  for (std::size_t p = 0; p < P.size(); ++p)
    if (!std::isfinite(P.temperature[p]))
      throw RunFault(
          fmt::format("{}: temperature {} K (not finite; is the material's "
                      "specific_heat too small?)",
                      bodies::describe_point(s, p), P.temperature[p]));
}

void check_budget_is_finite(const bodies::Bodies& s, const metrics::EnergyBudget& e) {
  if (std::isfinite(e.kinetic) && std::isfinite(e.internal) && std::isfinite(e.viscous) &&
      std::isfinite(e.absorbed) && std::isfinite(e.contact) && std::isfinite(e.departed))
    return;
  throw RunFault(fmt::format(
      "the energy budget is not finite at t = {:.6g} ns: kinetic {:.4g} J, internal {:.4g} J, "
      "viscous {:.4g} J, absorbed {:.4g} J, contact {:.4g} J, departed {:.4g} J",
      s.time * 1e9, e.kinetic, e.internal, e.viscous, e.absorbed, e.contact, e.departed));
}

// Nothing in a case drives a body: held faces do no work (their velocity is zero), dashpots only
// take energy, contact and bonds pass it between bodies or dissipate it; an adhesive contact's
// well gives out what it has taken in, the energy its attraction released so far, and a grip
// what its work gave (FaultChecks::check adds either to E0). So no body's kinetic energy
// can exceed the run's initial total E0 (by more than the budget's tolerance), and a body's mean
// motion carries |p|^2 / 2M, no more than its points' kinetic energy (Cauchy-Schwarz; with ring
// masses in r-z too). A body faster than sqrt(2 (1 + kEnergyGrowthLimit) E0 / M) has been driven by
// the numerics. A valid run cannot reach the bound without breaking the budget; a broken one can
// while its ledger hides it (a negative absorbed or contact term), and the bound does not read the
// ledger.
void check_mean_velocities(const bodies::Bodies& s, double initial_total, double allowed) {
  for (const bodies::BodyRange& b : s.bodies) {
    const bodies::Points& P = s.points;
    double mass = 0.0, momentum[3] = {0.0, 0.0, 0.0};
    for (std::size_t p = b.begin; p < b.end; ++p) {
      mass += P.mass[p];
      for (int d = 0; d < 3; ++d) momentum[d] += P.mass[p] * P.velocity[d][p];
    }
    if (mass <= 0.0) continue;  // every point has left the grid
    const double p2 =
        momentum[0] * momentum[0] + momentum[1] * momentum[1] + momentum[2] * momentum[2];
    if (p2 / (2.0 * mass) <= allowed) continue;
    throw RunFault(fmt::format(
        "body '{}': mean velocity {:.4g} m/s at t = {:.6g} ns, faster than the {:.4g} m/s that "
        "the run's initial total energy {:.4g} J allows its mass {:.4g} kg (nothing drives a "
        "body: an instability; try a smaller solver.cfl or a finer grid)",
        b.name, std::sqrt(p2) / mass, s.time * 1e9, std::sqrt(2.0 * allowed / mass), initial_total,
        mass));
  }
}

}  // namespace

void FaultChecks::check(const bodies::Bodies& s, const metrics::EnergyBudget& e) const {
  check_temperatures(s);
  check_budget_is_finite(s, e);
  // A run that starts with no energy at all, bodies at rest, has no scale for the rest.
  if (initial_total_ <= 0.0) return;
  // What an adhesive well has released or a grip given: minus the budget's contact entry (the
  // work done against the contact forces and by the grip) where it is negative. It may drive the
  // bodies, and the budget's error scales with the energy that flows, so it widens both bounds
  // by the budget's tolerance on it too (a body a grip drags carries just what the grip gave).
  const double released = driven_ ? std::max(0.0, -e.contact) : 0.0;
  check_mean_velocities(s, initial_total_,
                        (1.0 + kEnergyGrowthLimit) * (initial_total_ + released));
  const double allowed =
      (1.0 + kEnergyGrowthLimit) * initial_total_ + kEnergyGrowthLimit * released;
  // The total with every term signed as it is: a term that went wrong in sign (absorbed, below)
  // lowers it, which is why it is checked on its own too.
  if (e.total() > allowed)
    throw RunFault(
        fmt::format("total energy grew to {:.4g} J from {:.4g} J at t = {:.6g} ns "
                    "(an instability: try a smaller solver.cfl)",
                    e.total(), initial_total_, s.time * 1e9));
  // The dashpots' force opposes each absorbing point's velocity, so their work is taken from the
  // bodies and goes below zero only by the budget's error. Below that, they have given energy
  // back: an unstable dashpot, as in issue 24's reproducer (a grid cell coarser than the bodies),
  // where the substrate's velocity flips sign and grows each step while the negative absorbed
  // term keeps the total from growing.
  if (e.absorbed < -kEnergyGrowthLimit * initial_total_)
    throw RunFault(fmt::format(
        "the absorbing faces gave back {:.4g} J by t = {:.6g} ns, {:.3g} times the run's initial "
        "total energy {:.4g} J (dashpots only take energy: an instability of the absorbing "
        "faces; try a finer grid or a smaller solver.cfl)",
        -e.absorbed, s.time * 1e9, -e.absorbed / initial_total_, initial_total_));
}

}  // namespace coldspray::run
