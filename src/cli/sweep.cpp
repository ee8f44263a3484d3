// `coldspray sweep CASE.yaml --vary KEY=V1,V2 | KEY=START:STOP:STEP ...`: a case run over the
// combinations of the varied keys, in parallel, resumable, spread over MPI ranks under mpirun.
#include "studies/sweep.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/thread_count.hpp"
#include "studies/mpi_session.hpp"
#include "studies/study_lock.hpp"

namespace coldspray::cli {

void add_sweep(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::vector<std::string> vary, sets;
    std::string out_dir;
    int jobs = 1;
    int threads_per_job = 0;
    bool quiet = false;
    bool pull_off = false;
    double grip = 0.5;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("sweep", "Run a case over combinations of varied keys");
  sub->add_option("case", opt->case_path, "Case file (YAML)")->required()->check(given_path());
  sub->add_option("--vary", opt->vary, "KEY=V1,V2,... or KEY=START:STOP:STEP (repeatable)")
      ->required();
  sub->add_option("--set", opt->sets, "Override a key in every case: KEY=VALUE (repeatable)");
  sub->add_option("--out", opt->out_dir, "Output folder (default out/NAME-sweep)")
      ->check(given_path());
  sub->add_option("--jobs", opt->jobs, "Cases run at once in this process (default 1)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads-per-job", opt->threads_per_job,
                  "OpenMP threads per case (default: the cores shared among the jobs)")
      ->check(machine_threads());
  sub->add_flag("--pull-off", opt->pull_off,
                "Then pull each finished case off (coldspray pull-off's defaults) into its "
                "folder's pull-off/, with pull_off.* columns in sweep.csv");
  sub->add_option("--grip", opt->grip, "With --pull-off: the share of the body that is gripped")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  sub->add_flag("--quiet", opt->quiet, "No progress line");
  sub->callback([opt] {
    std::vector<case_file::Override> base;
    for (const auto& s : opt->sets) base.push_back(case_file::parse_override(s));
    std::vector<studies::Variation> vary;
    for (const auto& v : opt->vary) vary.push_back(studies::parse_variation(v));
    const case_file::Case c = case_file::load_case(opt->case_path, base);

    const studies::MpiSession mpi;
    studies::SweepOptions options;
    options.out_dir = opt->out_dir.empty() ? "out/" + c.name + "-sweep" : opt->out_dir;
    options.jobs = opt->jobs;
    options.threads_per_job = opt->threads_per_job;
    options.progress = !opt->quiet;
    options.rank = mpi.rank();
    options.ranks = mpi.size();
    studies::check_sweep_cases(opt->case_path, base, vary);
    const auto lock = studies::lock_study_folder(options.out_dir, mpi);
    if (opt->pull_off) {
      studies::PullOffOptions pull;
      pull.fraction = opt->grip;
      options.pull_off = pull;
    }
    const studies::SweepCounts n = studies::run_sweep(opt->case_path, base, vary, options);
    mpi.barrier();
    if (mpi.rank() == 0)
      studies::write_sweep_csv(options.out_dir, vary, studies::sweep_cases(vary));
    std::cout << fmt::format(
        "sweep{}: {} cases, {} run now ({} failed), {} finished before; table {}/sweep.csv\n",
        mpi.size() > 1 ? fmt::format(" rank {}/{}", mpi.rank(), mpi.size()) : "", n.cases, n.ran,
        n.failed, n.skipped, options.out_dir.string());
  });
}

}  // namespace coldspray::cli
