// `coldspray check CASE.yaml`: parse and validate a case, print what it describes, write nothing.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "case/load.hpp"
#include "cli/case_summary.hpp"
#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/run_report.hpp"

namespace coldspray::cli {

void add_check(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::vector<std::string> sets;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("check", "Validate a case file without running it");
  sub->add_option("case", opt->case_path, "Case file (YAML)")->required()->check(given_path());
  sub->add_option("--set", opt->sets, "Override a key: KEY=VALUE (repeatable)");
  sub->callback([opt] {
    const case_file::Case c = case_file::load_case(opt->case_path, parse_overrides(opt->sets));
    print_case_summary(c, std::cout);
    std::cout << fmt::format("{}: OK\n", opt->case_path);
  });
}

}  // namespace coldspray::cli
