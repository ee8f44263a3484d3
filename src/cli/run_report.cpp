#include "cli/run_report.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <ostream>

#include "cli/case_summary.hpp"
#include "cli/path_option.hpp"
#include "cli/thread_count.hpp"
#include "core/error.hpp"
#include "run/checkpoints.hpp"
#include "run/run.hpp"

namespace coldspray::cli {

namespace fs = std::filesystem;

void add_run_flags(CLI::App& sub, RunFlags& flags) {
  sub.add_option("--out", flags.out_dir, "Output folder (default out/NAME)")->check(given_path());
  sub.add_flag("--overwrite", flags.overwrite,
               "Replace the results of a previous run in the output folder");
  sub.add_option("--set", flags.sets, "Override a key: KEY=VALUE (repeatable)");
  sub.add_option("--threads", flags.threads, "OpenMP threads (default: all cores)")
      ->check(machine_threads());
  sub.add_flag("--quiet", flags.quiet, "No progress line");
}

std::vector<case_file::Override> parse_overrides(const std::vector<std::string>& sets) {
  std::vector<case_file::Override> overrides;
  for (const auto& s : sets) overrides.push_back(case_file::parse_override(s));
  return overrides;
}

case_file::Case restart_case(const std::string& run_or_checkpoint, RunFlags& flags) {
  // The case is the checkpoint's: a restarted run is the run it continues.
  if (!flags.sets.empty() || !flags.out_dir.empty())
    throw InputError("--restart", "",
                     "continues a run as it was: --set and --out do not apply to it");
  flags.restart_from = run::find_checkpoint(run_or_checkpoint);
  if (fs::absolute(flags.restart_from).parent_path().filename() != "checkpoints")
    throw InputError("--restart", "",
                     fmt::format("'{}' is not in a run folder's checkpoints/: a run continues in "
                                 "the folder that wrote it",
                                 flags.restart_from.string()));
  flags.out_dir = flags.restart_from.parent_path().parent_path().string();
  flags.lock = std::make_shared<io::FolderLock>(flags.out_dir, "--restart");
  return run::checkpoint_case(flags.restart_from);
}

std::filesystem::path run_folder(const case_file::Case& c, const RunFlags& flags) {
  return flags.out_dir.empty() ? "out/" + c.name : flags.out_dir;
}

Report run_and_report(const case_file::Case& c, const RunFlags& flags, std::ostream& out) {
  if (flags.threads > 0) omp_set_num_threads(flags.threads);
  run::RunOptions options;
  options.out_dir = run_folder(c, flags);
  print_case_summary(c, out);
  options.restart_command = flags.restart_command;
  options.progress = !flags.quiet;
  options.restart_from = flags.restart_from;
  options.initial_state = flags.initial_state;
  options.refuse_previous_results = !flags.overwrite;
  options.lock = flags.lock;
  const run::Summary s = run::run_case(c, options);
  out << fmt::format(
      "done: {} steps to t = {:.4g} ns in {:.1f} s on {} threads ({:.3g} particle-steps/s)\n"
      "energy: kinetic {:.4g} J, elastic {:.4g} J, plastic work {:.4g} J, viscous {:.4g} J, "
      "absorbed {:.4g} J, contact {:.4g} J{}; budget error {:.2e}\n",
      s.steps, s.time * 1e9, s.wall_seconds, s.threads, s.particle_steps_per_second,
      s.energy.kinetic, s.energy.elastic(), s.energy.plastic_work, s.energy.viscous,
      s.energy.absorbed, s.energy.contact,
      s.energy.departed != 0.0 ? fmt::format(", departed {:.4g} J", s.energy.departed) : "",
      s.energy_relative_error());
  for (const auto& b : s.bodies) {
    out << fmt::format(
        "  {}: velocity ({:.4g}, {:.4g}, {:.4g}) m/s, max eqps {:.3g}, mean eqps {:.3g}, "
        "max T {:.0f} K",
        b.name, b.velocity[0], b.velocity[1], b.velocity[2], b.max_eqps, b.mean_eqps,
        b.max_temperature);
    if (b.departed.points > 0)
      out << fmt::format("; {} points, {:.3g} % of its mass, left the grid", b.departed.points,
                         100.0 * b.departed.mass / (b.mass + b.departed.mass));
    out << "\n";
  }
  return {s, options.out_dir};
}

void print_results_location(const std::filesystem::path& out_dir, std::ostream& out) {
  out << fmt::format("results in {}/ (summary.json, history.csv; ParaView: {}/snapshots.pvd)\n",
                     out_dir.string(), out_dir.string());
}

}  // namespace coldspray::cli
