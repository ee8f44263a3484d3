// What a run reports: status, counts, timing, the energy budget and per-body measures;
// written as summary.json and returned to in-process callers (studies).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "metrics/body_metrics.hpp"
#include "metrics/energy.hpp"

namespace coldspray::run {

struct Summary {
  std::string status = "ok";  // "ok", "fault: <message>" or "interrupted"
  long steps = 0;
  double time = 0.0;          // simulated, s
  double wall_seconds = 0.0;  // of a bond-family member, with the shared steps in full
  long shared_steps = 0;      // steps shared with other runs (run/bond_family.hpp)
  int extensions = 0;         // verdict windows the run was extended by while undecided
  int threads = 1;
  std::size_t particles = 0;
  bodies::Discretisation discretisation;
  double particle_steps_per_second = 0.0;
  double last_dt = 0.0;
  metrics::EnergyBudget energy;
  double total_energy_initial = 0.0;
  std::vector<metrics::BodyMetrics> bodies;

  double energy_relative_error() const {
    return (energy.total() - total_energy_initial) / total_energy_initial;
  }
};

void write_summary_json(const Summary& s, const std::filesystem::path& path);

// summary.json's fields as dotted names ("energy.kinetic", "bodies.<name>.mass") with units, in
// written order: docs/outputs.md's table lists the same (tests/run/output_fields_test.cpp).
std::vector<std::pair<std::string, std::string>> summary_field_units();

}  // namespace coldspray::run
