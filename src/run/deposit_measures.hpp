// What `coldspray deposit` measures of a run's last state (docs/deposit.md, "Measures"): the
// deposition efficiency and the deposit's shape, from the points a checkpoint holds.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "case/case.hpp"
#include "metrics/deposit_metrics.hpp"

namespace coldspray::run {

struct DepositMeasures {
  double efficiency = 0.0;  // mass of the bonded particles over the mass sprayed
  metrics::DepositShape shape;
};

// The measures of the deposit in the state checkpoint `file` (of case `c`) holds: the bodies
// before the last are the particles, sprayed_mass and bonded theirs; the last is the substrate,
// whose top face was z = 0. Voxels of edge `edge` over the patch (metrics::voxelise_deposit), the
// bonded particles' points faster than the case's metrics.rest_speed_limit (jets) left out.
DepositMeasures deposit_measures(const case_file::Case& c, const std::filesystem::path& file,
                                 const std::vector<double>& sprayed_mass,
                                 const std::vector<bool>& bonded, std::array<double, 2> patch,
                                 double edge);

}  // namespace coldspray::run
