#include "run/interface_areas.hpp"

#include <numbers>

#include "metrics/impact_metrics.hpp"
#include "run/checkpoints.hpp"
#include "run/solver.hpp"

namespace coldspray::run {

InterfaceAreas interface_areas(const case_file::Case& c, const std::filesystem::path& file,
                               std::size_t body) {
  SolverState state = build_solver_state(c);
  return std::visit(
      [&](auto& s) {
        load_initial_state(file, s);
        // The footprint's diameter: the flattening ratio's 2 r + h = ratio x initial diameter.
        const double d =
            metrics::impact_measures(s, body).flattening_ratio * s.bodies[body].initial_diameter;
        return InterfaceAreas{metrics::touching_area(s, body), std::numbers::pi * d * d / 4.0};
      },
      state);
}

}  // namespace coldspray::run
