// `coldspray run CASE.yaml`: validate a case, run it, print where the results are.
// `coldspray run --restart RUN_OR_CHECKPOINT`: continue a run from its checkpoint, in its folder.
#include <iostream>
#include <memory>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/run_report.hpp"
#include "core/error.hpp"

namespace coldspray::cli {

void add_run(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::string restart;
    RunFlags run;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("run", "Run a case file");
  auto* case_option =
      sub->add_option("case", opt->case_path, "Case file (YAML)")->check(given_path());
  sub->add_option("--restart", opt->restart,
                  "Continue a run from its latest checkpoint (a run folder) or from a "
                  "checkpoint file, in the run's folder")
      ->excludes(case_option)
      ->check(given_path());
  sub->add_option("--initial-state", opt->run.initial_state,
                  "Start the case from a checkpoint's state (same bodies), at t = 0")
      ->excludes("--restart")
      ->check(given_path());
  add_run_flags(*sub, opt->run);
  sub->callback([opt] {
    if (opt->restart.empty() && opt->case_path.empty())
      throw InputError("run", "", "needs a case file, or --restart RUN_FOLDER");
    const case_file::Case c =
        opt->restart.empty() ? case_file::load_case(opt->case_path, parse_overrides(opt->run.sets))
                             : restart_case(opt->restart, opt->run);
    const Report report = run_and_report(c, opt->run, std::cout);
    print_results_location(report.out_dir, std::cout);
  });
}

}  // namespace coldspray::cli
