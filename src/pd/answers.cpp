#include "pd/answers.hpp"

#include <fmt/format.h>

#include "metrics/impact_metrics.hpp"

namespace coldspray::pd {

std::string describe_discretisation(Solver, const case_file::Case& c, double /*unit*/,
                                    std::string_view /*symbol*/) {
  return fmt::format("  peridynamics, horizon {:.4g} x spacing\n", c.peridynamics->horizon_factor);
}

bool holds_bonds(Solver, const case_file::Case& c) {
  return c.contact.peridynamics.model != case_file::ContactModel::Repulsive;
}

std::string_view unbonded_reason(Solver) {
  return "was run with the repulsive contact (contact.peridynamics.model: repulsive): no adhesion "
         "holds the "
         "splat to pull off";
}

// Three spacings of the splat: beyond the reach of either adhesive law.
double default_pull_distance(Solver, const case_file::Case& c, std::size_t body,
                             const metrics::InterfaceAreas& /*areas*/) {
  return 3.0 * c.bodies[body].spacing;
}

void measure_bonds(const case_file::Case& /*c*/, const State& s, std::size_t body,
                   metrics::InterfaceAreas& areas) {
  areas.bonded = metrics::touching_area(s, body);
}

}  // namespace coldspray::pd
