// The deposit file of `coldspray deposit` (docs/deposit.md): the particles (how many, their
// material, size distribution, speed against size, temperature), the substrate, the patch they
// land on, their arrival window, the seed, the grid and the bonding model. Read with the case
// reader's schema machinery, so a problem is an InputError naming FILE:LINE:COLUMN and the key.
#pragma once

#include <string>

#include "studies/deposit_placement.hpp"

namespace coldspray::setups {

struct DepositFile {
  std::string path;
  std::string name, description;
  std::string material, substrate_material;  // substrate_material: the particles' if not given
  double temperature = 298.0;                // particles, K
  double substrate_temperature = 298.0;      // K
  double substrate_thickness = 10e-6;        // m
  double substrate_margin = 0.0;             // substrate beyond the patch on each side, m
  int coarsening = 0;                        // levels of the substrate's coarsened seeding
  double cell_size = 0.0, spacing = 0.0;     // m
  double settle_time = 80e-9;                // s, run on after the last arrival
  double verdict_window = 20e-9;             // s, the cases' metrics.verdict_window
  double voxel = 0.0;                        // the porosity's voxel edge, m (default: spacing)
  std::string bonding = "energy";
  std::string contact_normal = "substrate";  // or a contact.mpm.normal (deposit_file.cpp)
  studies::DepositPlan plan;
  // Where values were given, "FILE:LINE:COLUMN", for errors found after reading (placement)
  // and for the generated case's keys.
  std::string particles_where, count_where, patch_where, grid_where, substrate_where, file_where;
};

// Reads and checks the file; InputError (exit 2) naming the file, line and key.
DepositFile read_deposit_file(const std::string& path);

}  // namespace coldspray::setups
