// `coldspray run CASE.yaml`: validate a case, run it, print where the results are.
#include "run/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <iostream>
#include <memory>

#include "case/load.hpp"
#include "cli/case_summary.hpp"
#include "cli/commands.hpp"

namespace coldspray::cli {

void add_run(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::string out_dir;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("run", "Run a case file");
  sub->add_option("case", opt->case_path, "Case file (YAML)")->required();
  sub->add_option("--out", opt->out_dir, "Output folder (default out/NAME)");
  sub->add_option("--set", opt->sets, "Override a key: KEY=VALUE (repeatable)");
  sub->add_option("--threads", opt->threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--quiet", opt->quiet, "No progress line");
  sub->callback([opt] {
    std::vector<case_file::Override> overrides;
    for (const auto& s : opt->sets) overrides.push_back(case_file::parse_override(s));
    const case_file::Case c = case_file::load_case(opt->case_path, overrides);
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    print_case_summary(c, std::cout);
    run::RunOptions options;
    options.out_dir = opt->out_dir.empty() ? "out/" + c.name : opt->out_dir;
    options.progress = !opt->quiet;
    const run::Summary s = run::run_case(c, options);
    std::cout << fmt::format(
        "done: {} steps to t = {:.4g} ns in {:.1f} s on {} threads ({:.3g} particle-steps/s)\n"
        "energy: kinetic {:.4g} J, elastic {:.4g} J, plastic work {:.4g} J, viscous {:.4g} J, "
        "absorbed {:.4g} J, contact {:.4g} J; budget error {:.2e}\n",
        s.steps, s.time * 1e9, s.wall_seconds, s.threads, s.particle_steps_per_second,
        s.energy.kinetic, s.energy.elastic(), s.energy.plastic_work, s.energy.viscous,
        s.energy.absorbed, s.energy.contact, s.energy_relative_error());
    for (const auto& b : s.bodies)
      std::cout << fmt::format(
          "  {}: velocity ({:.4g}, {:.4g}, {:.4g}) m/s, max eqps {:.3g}, mean eqps {:.3g}, "
          "max T {:.0f} K\n",
          b.name, b.velocity[0], b.velocity[1], b.velocity[2], b.max_eqps, b.mean_eqps,
          b.max_temperature);
    std::cout << fmt::format(
        "results in {}/ (summary.json, history.csv; ParaView: {}/snapshots.pvd)\n",
        options.out_dir.string(), options.out_dir.string());
  });
}

}  // namespace coldspray::cli
