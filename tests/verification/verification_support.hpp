// Running a verification case in-process and reading its outputs.
#pragma once

#include <string>
#include <vector>

#include "run/summary.hpp"
#include "table.hpp"

namespace coldspray::verification {

using testing::read_table;
using testing::Table;

struct CaseRun {
  run::Summary summary;
  std::string out_dir;
  Table history() const { return read_table(out_dir + "/history.csv"); }
  Table probes() const { return read_table(out_dir + "/probes.csv"); }
};

// Runs examples/verification/NAME.yaml (with optional --set style overrides) into a fresh
// temporary folder.
CaseRun run_verification_case(const std::string& name,
                              const std::vector<std::pair<std::string, std::string>>& sets = {});

// The first time at which `values` crosses `level` (going the way from its first value),
// linearly interpolated; -1 if it never does.
double crossing_time(const std::vector<double>& time, const std::vector<double>& values,
                     double level);

// Mean of values over times in [t0, t1].
double mean_over(const std::vector<double>& time, const std::vector<double>& values, double t0,
                 double t1);

}  // namespace coldspray::verification
