// `coldspray run CASE.yaml`: validate a case, run it, print where the results are.
#include <iostream>
#include <memory>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/run_report.hpp"

namespace coldspray::cli {

void add_run(CLI::App& app) {
  struct Options {
    std::string case_path;
    RunFlags run;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("run", "Run a case file");
  sub->add_option("case", opt->case_path, "Case file (YAML)")->required();
  add_run_flags(*sub, opt->run);
  sub->callback([opt] {
    const case_file::Case c = case_file::load_case(opt->case_path, parse_overrides(opt->run.sets));
    const Report report = run_and_report(c, opt->run, std::cout);
    print_results_location(report.out_dir, std::cout);
  });
}

}  // namespace coldspray::cli
