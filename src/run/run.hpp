// Running a case: the one library entry point that the CLI and the studies call.
#pragma once

#include <filesystem>

#include "case/case.hpp"
#include "run/summary.hpp"

namespace coldspray::run {

struct RunOptions {
  std::filesystem::path out_dir;  // created if missing
  bool progress = true;           // a progress line on stderr
};

// A run whose total energy grows past (1 + this) times its initial total stops as a fault.
inline constexpr double kEnergyGrowthLimit = 0.2;

// Runs the case and writes its results into options.out_dir: case.resolved.yaml, summary.json,
// history.csv, probes.csv (with probes), snapshots/*.vtu and snapshots.pvd. Throws InputError
// before writing anything if the case's geometry is invalid; on a fault during the run, writes
// a last snapshot and a summary with the fault as status, then throws RunFault.
Summary run_case(const case_file::Case& c, const RunOptions& options);

}  // namespace coldspray::run
