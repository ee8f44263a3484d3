// A deposit's deposit.json (docs/outputs.md, "deposit.json"), written from declared fields
// (io/output_schema.hpp): the file's name, seed and patch, the deposit's measures, each particle's
// placement, verdict and measures, and the thickness map.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/output_schema.hpp"
#include "run/deposit_measures.hpp"
#include "run/summary.hpp"
#include "studies/deposit_placement.hpp"

namespace coldspray::studies {

// One particle of the deposit: where it was placed and what became of it.
struct ParticleRow {
  std::string name;
  const PlacedParticle* placed = nullptr;
  const metrics::BodyMetrics* body = nullptr;
  double sprayed_mass = 0.0;                                    // kg, departed points included
  double bonded_to_particles = 0.0, bonded_to_substrate = 0.0;  // m^2
  bool bonded = false;
};

// What deposit.json is written from: the deposit file's name, plan and voxel edge (m), its
// particles' rows and the deposit's measures.
struct DepositReport {
  const std::string& name;
  const DepositPlan& plan;
  double voxel;
  const std::vector<ParticleRow>& rows;
  const run::DepositMeasures& deposit;
};

// Writes deposit.json at `path`.
void write_deposit_json(const std::filesystem::path& path, const DepositReport& report);

// Its fields with their units, in written order: docs/outputs.md's table lists the same
// (tests/run/output_fields_test.cpp).
io::FieldUnits deposit_field_units();

}  // namespace coldspray::studies
