// `coldspray deposit DEPOSIT.yaml`: many particles sprayed onto a substrate in one 3D run
// (docs/deposit.md). Places the particles (studies/deposit_placement.hpp), builds the case
// (setups/deposit_case.hpp), runs it, then reports each particle's verdict and measures and the
// deposit's: deposition efficiency, porosity, thickness (run/deposit_measures.hpp), into
// RUN/deposit.json and on the terminal.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/impact_options.hpp"
#include "cli/path_option.hpp"
#include "cli/run_report.hpp"
#include "core/error.hpp"
#include "geometry/shape.hpp"
#include "io/atomic_file.hpp"
#include "run/checkpoints.hpp"
#include "run/deposit_measures.hpp"
#include "run/interrupt.hpp"
#include "setups/deposit_case.hpp"
#include "setups/deposit_file.hpp"
#include "setups/deposit_limits.hpp"
#include "studies/deposit_json.hpp"

namespace coldspray::cli {

namespace {

struct DepositCommandOptions {
  std::string path, write_case, restart;
  RunFlags run;
};

// A restarted deposit's case is its checkpoint's; the file's placement must be the one it was
// made from (the same particles, sizes, starts and speeds), since the report reads them from it.
void check_same_particles(const case_file::Case& c, const studies::Placement& placement,
                          const std::string& file) {
  const std::vector<std::string> names =
      setups::particle_names(static_cast<int>(placement.particles.size()));
  bool same = c.bodies.size() == names.size() + 1;
  for (std::size_t i = 0; same && i < names.size(); ++i) {
    const studies::PlacedParticle& p = placement.particles[i];
    const auto* sphere = std::get_if<geometry::Sphere>(&c.bodies[i].shape);
    // The case file holds 12 significant digits of each length and speed.
    const double tolerance = 1e-9 * p.diameter;
    same = c.bodies[i].name == names[i] && sphere &&
           std::abs(2.0 * sphere->radius - p.diameter) < tolerance &&
           std::abs(c.bodies[i].velocity[2] + p.speed) < 1e-9 * p.speed;
    for (int d = 0; same && d < 3; ++d)
      same = std::abs(sphere->center[d] - p.centre[d]) < tolerance;
  }
  if (!same)
    throw InputError("--restart", "",
                     fmt::format("the run's bodies are not the particles {} places: restart a "
                                 "deposit with the file it was run from",
                                 file));
}

using studies::ParticleRow;

std::vector<ParticleRow> particle_rows(const studies::Placement& placement,
                                       const run::Summary& summary) {
  const std::vector<std::string> names =
      setups::particle_names(static_cast<int>(placement.particles.size()));
  const std::size_t substrate = summary.bodies.size() - 1;
  std::vector<ParticleRow> rows;
  for (std::size_t i = 0; i < names.size(); ++i) {
    ParticleRow r;
    r.name = names[i];
    r.placed = &placement.particles[i];
    r.body = &summary.bodies[i];
    r.sprayed_mass = r.body->mass + r.body->departed.mass;
    const std::vector<double>& with = r.body->impact.bonded_area_with;
    for (std::size_t o = 0; o < with.size(); ++o)
      (o == substrate ? r.bonded_to_substrate : r.bonded_to_particles) += with[o];
    r.bonded = r.body->verdict && r.body->verdict->outcome == metrics::Outcome::Bonded;
    rows.push_back(r);
  }
  return rows;
}

void print_deposit(const std::vector<ParticleRow>& rows, const run::DepositMeasures& deposit,
                   std::ostream& out) {
  const metrics::DepositShape& shape = deposit.shape;
  out << "particle  d (um)  v (m/s)  arrival (ns)  verdict    cor      flattening  bonded area "
         "(um^2): to particles / to substrate\n";
  for (const ParticleRow& r : rows) {
    const metrics::ImpactMeasures& m = r.body->impact;
    out << fmt::format(
        "{:<9} {:<7.4g} {:<8.4g} {:<13.4g} {:<10} {:<8.3g} {:<11.4g} {:.4g} / {:.4g}\n", r.name,
        r.placed->diameter * 1e6, r.placed->speed, r.placed->arrival * 1e9,
        r.body->verdict ? metrics::outcome_name(r.body->verdict->outcome) : "none", m.cor,
        m.flattening_ratio, r.bonded_to_particles * 1e12, r.bonded_to_substrate * 1e12);
  }
  int bonded = 0;
  for (const ParticleRow& r : rows) bonded += r.bonded ? 1 : 0;
  out << fmt::format(
      "deposit: {} of {} particles bonded, deposition efficiency {:.3g} %, porosity {:.3g} %, "
      "thickness {:.3g} um mean over the patch ({:.3g} um at most), coverage {:.3g} %\n",
      bonded, rows.size(), 100.0 * deposit.efficiency, 100.0 * shape.porosity,
      shape.mean_thickness * 1e6, shape.max_thickness * 1e6, 100.0 * shape.coverage);
}

// The deposit's measures from the run's last checkpoint. Measuring seeds the case again, and a
// signal then stops it as it stops a run's set-up, but the run's results are written by then:
// the message says so, and how to report them.
run::DepositMeasures measure_deposit(const setups::DepositFile& file, const case_file::Case& c,
                                     const std::filesystem::path& out_dir,
                                     const std::vector<double>& masses,
                                     const std::vector<bool>& bonded) {
  try {
    return run::deposit_measures(c, run::find_checkpoint(out_dir), masses, bonded, file.plan.patch,
                                 file.voxel);
  } catch (const run::Interrupted& e) {
    throw run::Interrupted(
        e.signal(),
        fmt::format("interrupted while measuring the deposit; the run's results are in "
                    "{}, deposit.json was not written: report them with coldspray "
                    "deposit {} --restart {}",
                    out_dir.string(), shell_quoted(file.path), shell_quoted(out_dir.string())));
  }
}

// The particles' rows and the deposit's measures from the finished run: deposit.json, the
// terminal's table, where the picture and the results are.
void report_deposit(const setups::DepositFile& file, const studies::Placement& placement,
                    const case_file::Case& c, const Report& report) {
  const std::vector<ParticleRow> rows = particle_rows(placement, report.summary);
  std::vector<double> masses;
  std::vector<bool> bonded;
  for (const ParticleRow& r : rows) {
    masses.push_back(r.sprayed_mass);
    bonded.push_back(r.bonded);
  }
  const run::DepositMeasures measures = measure_deposit(file, c, report.out_dir, masses, bonded);
  studies::write_deposit_json(report.out_dir / "deposit.json",
                              {file.name, file.plan, file.voxel, rows, measures});
  print_deposit(rows, measures, std::cout);
  std::cout << fmt::format(
      "picture: /usr/bin/python3 tools/coldspray_plot.py deposit {} --out {}\n",
      shell_quoted(report.out_dir.string()),
      shell_quoted((report.out_dir / "deposit.png").string()));
  print_results_location(report.out_dir, std::cout);
}

// What continues an interrupted deposit: its own command, which also writes deposit.json.
std::string deposit_restart_command(const std::string& deposit_file,
                                    const std::filesystem::path& folder) {
  return fmt::format("coldspray deposit {} --restart {}", shell_quoted(deposit_file),
                     shell_quoted(folder.string()));
}

}  // namespace

void add_deposit(CLI::App& app) {
  auto opt = std::make_shared<DepositCommandOptions>();
  auto* sub = app.add_subcommand(
      "deposit",
      "Spray many particles onto a substrate in one 3D run and measure the deposit "
      "(docs/deposit.md)");
  sub->add_option("deposit", opt->path, "Deposit file (YAML)")->required()->check(given_path());
  auto* write =
      sub->add_option("--write-case", opt->write_case,
                      "Write the generated case file and stop (edit it, then `coldspray run` it)")
          ->check(given_path());
  sub->add_option("--restart", opt->restart,
                  "Continue the deposit's run from its latest checkpoint (its run folder), then "
                  "report it")
      ->excludes(write)
      ->check(given_path());
  add_run_flags(*sub, opt->run);
  sub->callback([opt] {
    const setups::DepositFile file = setups::read_deposit_file(opt->path);
    if (!opt->write_case.empty()) io::require_writable(opt->write_case, "--write-case");
    const std::vector<case_file::Override> sets = parse_overrides(opt->run.sets);
    setups::check_deposit_size(file, sets);
    const studies::Placement placement = setups::deposit_placement(file);
    if (!opt->restart.empty()) {
      const case_file::Case c = restart_case(opt->restart, opt->run);
      opt->run.restart_command = deposit_restart_command(opt->path, opt->run.out_dir);
      check_same_particles(c, placement, opt->path);
      report_deposit(file, placement, c, run_and_report(c, opt->run, std::cout));
      return;
    }
    const setups::GeneratedCase g = setups::deposit_case(file, placement);
    const case_file::Case c =
        case_file::load_case_text(opt->path + " (its generated case)", g.yaml, g.origins, sets);
    // Reading the case does not read the stop flag (under a second for 1000 particles, 0.9 s
    // with their placement); a signal during it stops here, before --write-case writes.
    stop_set_up_if_interrupted("reading the generated case");
    if (!opt->write_case.empty()) {
      io::write_atomically(opt->write_case, [&](std::ostream& out) { out << g.yaml; });
      std::cout << fmt::format("wrote {} (run it with: coldspray run {})\n", opt->write_case,
                               shell_quoted(opt->write_case));
      return;
    }
    opt->run.restart_command = deposit_restart_command(opt->path, run_folder(c, opt->run));
    report_deposit(file, placement, c, run_and_report(c, opt->run, std::cout));
  });
}

}  // namespace coldspray::cli
