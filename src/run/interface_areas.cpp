#include "run/interface_areas.hpp"

#include <numbers>

#include "metrics/impact_metrics.hpp"
#include "run/checkpoints.hpp"
#include "run/solver.hpp"

namespace coldspray::run {

metrics::InterfaceAreas interface_areas(const case_file::Case& c, const std::filesystem::path& file,
                                        std::size_t body) {
  SolverState state = build_solver_state(c);
  return std::visit(
      [&](auto& s) {
        load_initial_state(file, s);
        metrics::InterfaceAreas a;
        // The footprint's diameter: the flattening ratio's 2 r + h = ratio x initial diameter.
        const double d =
            metrics::impact_measures(s, body, metrics::SplatExtent::Measured).flattening_ratio *
            s.bodies[body].initial_diameter;
        a.projected = std::numbers::pi * d * d / 4.0;
        a.mirror_plane = s.bodies[body].mirror_plane;
        a.axisymmetric = s.geometry == case_file::Geometry::Axisymmetric;
        measure_bonds(c, s, body, a);  // the solver's own (mpm/answers.hpp, pd/answers.hpp)
        return a;
      },
      state);
}

}  // namespace coldspray::run
