// `coldspray calibrate CALIB.yaml`: calibrates the bonding model's two parameters over a grid of
// impacts of two particle sizes at their critical velocities (thesis §4.1.2, §5.1.1-5.1.3).
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/thread_count.hpp"
#include "setups/calibration_file.hpp"
#include "studies/calibration.hpp"
#include "studies/mpi_session.hpp"
#include "studies/study_lock.hpp"

namespace coldspray::cli {

namespace {

// A parameter in the thesis' units: J/m^2/us for the energy rate (Table 5.1), else SI.
std::string parameter_text(const studies::ParameterAxis& axis, double value) {
  if (axis.key == "critical_energy_rate") return fmt::format("{:.5g} J/m^2/us", value * 1e-6);
  return fmt::format("{:.5g}{}", value, axis.unit == "-" ? "" : " " + axis.unit);
}

void print_results(const setups::CalibrationFile& file,
                   const std::vector<studies::GridResult>& results,
                   const std::filesystem::path& out_dir) {
  const studies::CalibrationPlan& plan = file.plan;
  for (const studies::GridResult& g : results) {
    std::cout << fmt::format("grid {}:\n", g.grid);
    for (std::size_t s = 0; s < plan.sizes.size(); ++s) {
      const studies::CalibrationSize& size = plan.sizes[s];
      const studies::SizeResult& r = g.sizes[s];
      std::cout << fmt::format(
          "  {} um at {:.6g} m/s: {} runs, {} bonded, {} not bonded{}{} ({})", size.diameter * 1e6,
          size.velocity, r.runs, r.bonded, r.not_bonded,
          r.undecided ? fmt::format(", {} undecided (left out)", r.undecided) : "",
          r.failed ? fmt::format(", {} failed or pending", r.failed) : "",
          studies::describe(size.classify));
      if (r.fit)
        std::cout << fmt::format("; fit accuracy {:.3g} in {} iterations{}", r.fit->accuracy,
                                 r.fit->iterations, r.fit->converged ? "" : " (not converged)");
      std::cout << "\n";
      if (!r.diagnosis.empty()) std::cout << "    " << r.diagnosis << "\n";
    }
    if (g.calibrated) {
      std::cout << fmt::format("  calibrated: {} = {}, {} = {}", plan.x1.key,
                               parameter_text(plan.x1, (*g.calibrated)[0]), plan.x2.key,
                               parameter_text(plan.x2, (*g.calibrated)[1]));
      if (g.intersections.size() > 1)
        std::cout << fmt::format(" (nearest the rectangle's centre of {} crossings)",
                                 g.intersections.size());
      std::cout << "\n";
      if (!g.diagnosis.empty()) std::cout << "    " << g.diagnosis << "\n";
    } else {
      std::cout << "  not calibrated: " << g.diagnosis << "\n";
    }
  }
  std::cout << fmt::format(
      "results in {}/ (calibration.json, runs.csv, boundary_*.csv); plot with "
      "tools/coldspray_plot.py calibration {}\n",
      out_dir.string(), out_dir.string());
}

void print_activation(const setups::CalibrationFile& file,
                      const std::vector<studies::ActivationGridResult>& results,
                      const std::filesystem::path& out_dir) {
  for (const studies::ActivationGridResult& g : results) {
    std::cout << fmt::format("grid {}:\n", g.grid);
    for (std::size_t s = 0; s < file.plan.sizes.size(); ++s) {
      const studies::CalibrationSize& size = file.plan.sizes[s];
      const studies::PenetrationLaw& law = g.laws[s];
      std::cout << fmt::format("  {:.6g} um at {:.6g} m/s: penetration {:.5g} (~ v^{:.3g})",
                               size.diameter * 1e6, size.velocity, law.at_velocity, law.exponent);
      if (s < g.predicted.size())
        std::cout << fmt::format(", vcrit {:.5g} m/s ({:+.2f} %)", g.predicted[s],
                                 100.0 * (g.predicted[s] / size.velocity - 1.0));
      std::cout << "\n";
    }
    if (g.critical_penetration)
      std::cout << fmt::format("  calibrated: critical_penetration = {:.5g}\n",
                               *g.critical_penetration);
    else
      std::cout << "  not calibrated: " << g.diagnosis << "\n";
  }
  std::cout << fmt::format(
      "results in {}/ (calibration.json, runs.csv); check with coldspray vcrit --set "
      "bonding.critical_penetration=VALUE\n",
      out_dir.string());
}

// Runs this rank's share of the study, then rank 0 analyses it.
void calibrate_file(const setups::CalibrationFile& file, const studies::CalibrationRunOptions& o,
                    const studies::MpiSession& mpi) {
  const studies::CalibrationCounts n = file.activation
                                           ? studies::run_activation_calibration(
                                                 setups::activation_plan(file),
                                                 [&](const studies::ActivationRun& run) {
                                                   return setups::activation_case(file, run);
                                                 },
                                                 o)
                                           : studies::run_calibration(
                                                 file.plan,
                                                 [&](const studies::CalibrationRun& run) {
                                                   return setups::calibration_case(file, run);
                                                 },
                                                 o);
  std::cout << fmt::format("calibrate{}: {} impacts, {} run now ({} failed), {} finished before\n",
                           mpi.size() > 1 ? fmt::format(" rank {}/{}", mpi.rank(), mpi.size()) : "",
                           n.runs, n.ran, n.failed, n.skipped);
  mpi.barrier();
  if (mpi.rank() != 0) return;
  if (file.activation)
    print_activation(
        file, studies::analyse_activation(setups::activation_plan(file), o.out_dir, file.name),
        o.out_dir);
  else
    print_results(file, studies::analyse_calibration(file.plan, o.out_dir, file.name), o.out_dir);
}

}  // namespace

void add_calibrate(CLI::App& app) {
  struct Options {
    std::string file, out_dir;
    int jobs = 1;
    int threads_per_job = 0;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand(
      "calibrate",
      "Calibrate the bonding model's parameters, or its activation, on particle sizes at their "
      "critical velocities (thesis §4.1.2, §5.1; docs/studies.md)");
  sub->add_option("file", opt->file, "Calibration file (YAML)")->required()->check(given_path());
  sub->add_option("--out", opt->out_dir, "Output folder (default out/NAME)")->check(given_path());
  sub->add_option("--jobs", opt->jobs, "Impacts run at once in this process (default 1)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads-per-job", opt->threads_per_job,
                  "OpenMP threads per impact (default: the cores shared among the jobs)")
      ->check(machine_threads());
  sub->add_flag("--quiet", opt->quiet, "No progress line");
  sub->callback([opt] {
    const setups::CalibrationFile file = setups::read_calibration_file(opt->file);
    const studies::MpiSession mpi;
    studies::CalibrationRunOptions o;
    o.out_dir = opt->out_dir.empty() ? "out/" + file.name : opt->out_dir;
    o.jobs = opt->jobs;
    o.threads_per_job = opt->threads_per_job;
    o.progress = !opt->quiet;
    o.rank = mpi.rank();
    o.ranks = mpi.size();
    const auto lock = studies::lock_study_folder(o.out_dir, mpi);
    calibrate_file(file, o, mpi);
  });
}

}  // namespace coldspray::cli
