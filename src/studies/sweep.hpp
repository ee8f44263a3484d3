// A sweep: one case file run over the combinations of varied keys, each combination in its own
// folder, in parallel inside one process (and across MPI ranks), resumable, with one row per
// case in sweep.csv.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "studies/case_runner.hpp"
#include "studies/pull_off.hpp"
#include "studies/variation.hpp"

namespace coldspray::studies {

struct SweepOptions {
  std::filesystem::path out_dir;
  int jobs = 1;             // cases run at once in this process
  int threads_per_job = 0;  // OpenMP threads of each case; 0: the cores shared among the jobs
  bool progress = true;     // a progress line on stderr
  int rank = 0;             // this process among `ranks` (MPI): it runs cases i % ranks == rank
  int ranks = 1;
  // With a value, each finished case is then pulled off (studies/pull_off.hpp) into its folder's
  // pull-off/ with these options (its impact and out set per case).
  std::optional<PullOffOptions> pull_off;
};

struct SweepCounts {
  std::size_t cases = 0;    // in the sweep
  std::size_t skipped = 0;  // finished by an earlier run (this rank's share)
  std::size_t ran = 0;      // run now (this rank's share)
  std::size_t failed = 0;   // of those run now: input error, fault or error
};

// One case of a sweep: its folder name and its overrides.
struct SweepCase {
  std::string folder;  // case_0001, ...
  std::vector<case_file::Override> overrides;
};

std::vector<SweepCase> sweep_cases(const std::vector<Variation>& vary);

// Loads the base case and every combination: InputError (naming --set or --vary) for the first
// that does not load.
void check_sweep_cases(const std::string& case_path, const std::vector<case_file::Override>& base,
                       const std::vector<Variation>& vary);

// Runs the cases of this rank not yet finished (check_sweep_cases first); writes DIR/sweep.csv
// (rank 0) after each case and at the end, from the summaries on disk. A failing case is recorded
// and the sweep goes on. With options.pull_off, then pulls off every finished case of this rank
// without a pull-off summary yet; a failing pull-off leaves its message in the case's
// pull-off-error.txt.
SweepCounts run_sweep(const std::string& case_path, const std::vector<case_file::Override>& base,
                      const std::vector<Variation>& vary, const SweepOptions& options);

// sweep.csv from the case folders on disk: case, status, the varied keys' values, the run's
// totals and each body's impact measures; where cases were pulled off, their pull-off's
// results (pull_off.*).
void write_sweep_csv(const std::filesystem::path& out_dir, const std::vector<Variation>& vary,
                     const std::vector<SweepCase>& cases);

}  // namespace coldspray::studies
