#include "run/deposit_measures.hpp"

#include "run/checkpoints.hpp"
#include "run/solver.hpp"

namespace coldspray::run {

DepositMeasures deposit_measures(const case_file::Case& c, const std::filesystem::path& file,
                                 const std::vector<double>& sprayed_mass,
                                 const std::vector<bool>& bonded, std::array<double, 2> patch,
                                 double edge) {
  DepositMeasures m;
  m.efficiency = metrics::deposition_efficiency(sprayed_mass, bonded);
  std::vector<bool> is_deposit = bonded;
  is_deposit.push_back(false);  // the substrate
  SolverState state = build_solver_state(c);
  m.shape = std::visit(
      [&](auto& s) {
        load_initial_state(file, s);
        const metrics::DepositVoxels voxels = metrics::voxelise_deposit(
            s, is_deposit, s.bodies.size() - 1, patch, edge, c.metrics.rest_speed_limit, 0.0);
        return metrics::deposit_shape(voxels, 0.0);
      },
      state);
  return m;
}

}  // namespace coldspray::run
