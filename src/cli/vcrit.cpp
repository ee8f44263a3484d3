// `coldspray vcrit --material NAME --diameters 14,18,22um ...`: the critical velocity of each
// particle size by bisection over the impact speed of the thesis' single-particle test, and the
// line vcrit = a + b d through them (thesis §5.2.2, Table 5.4).
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
#include "cli/quantity_option.hpp"
#include "cli/run_report.hpp"
#include "cli/thread_count.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "studies/critical_velocity.hpp"
#include "studies/mpi_session.hpp"
#include "studies/study_lock.hpp"

namespace coldspray::cli {

namespace {

constexpr const char* kSource = "coldspray vcrit";

struct VcritCommandOptions {
  ImpactCaseOptions impact;
  std::string diameters, vmin = "500m/s", vmax = "1200m/s", tol = "2m/s", out_dir;
  std::vector<std::string> sets;
  int max_runs = 16;
  int jobs = 1;
  int threads_per_job = 0;
  bool quiet = false;
};

// "14,18,22um" or "14um,18um": a unit after the last number applies to the bare ones before it.
std::vector<double> parse_diameters(const std::string& text) {
  std::vector<std::string> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const std::string& last = items.back();
  const std::size_t unit = last.find_first_not_of("0123456789.eE+- ");
  const std::string suffix = unit == std::string::npos ? "" : last.substr(unit);
  std::vector<double> diameters;
  for (std::string item : items) {
    if (item.find_first_not_of("0123456789.eE+- ") == std::string::npos) item += suffix;
    diameters.push_back(parse_diameter("--diameters", item));
  }
  return diameters;
}

std::string number_text(double x, const char* format) {
  return std::isnan(x) ? std::string("-") : fmt::format(fmt::runtime(format), x);
}

// The search's settings from the options; InputError at the option at fault.
studies::VcritOptions vcrit_options(const VcritCommandOptions& opt) {
  studies::VcritOptions o;
  o.diameters = parse_diameters(opt.diameters);
  o.vmin = parse_speed("--vmin", opt.vmin);
  o.vmax = parse_speed("--vmax", opt.vmax);
  o.tol = parse_option_quantity("--tol", opt.tol, units::kVelocity);
  if (!(o.vmax > o.vmin)) throw InputError("--vmax", "", "must be greater than --vmin");
  if (!(o.tol >= 1e-8 * o.vmax))
    throw InputError("--tol", "", fmt::format("must be >= {:.3g} m/s", 1e-8 * o.vmax));
  o.max_runs = opt.max_runs;
  o.jobs = opt.jobs;
  o.threads_per_job = opt.threads_per_job;
  o.progress = !opt.quiet;
  o.out_dir = opt.out_dir.empty() ? "out/vcrit-" + opt.impact.material : opt.out_dir;
  return o;
}

// The table of critical velocities, one line per diameter.
void print_vcrit_table(const std::string& material, const studies::VcritOptions& o,
                       const std::vector<studies::VcritRow>& rows) {
  std::cout << fmt::format(
      "vcrit of {} (search over {:.6g}-{:.6g} m/s to {:.3g} m/s, cut where the penetration "
      "reaches the critical one; bonded: the verdict of each "
      "impact's summary, undecided counted as not bonded):\n",
      material, o.vmin, o.vmax, o.tol);
  std::cout << "  d (um)  vcrit (m/s)  bracket (m/s)  margin at vcrit, below (m/s)  runs  "
               "undecided  status\n";
  for (const auto& r : rows)
    std::cout << fmt::format(
        "  {:<6.4g}  {:>11}  {:>13}  {:>28}  {:>4}  {:>9}  {}\n", r.diameter * 1e6,
        number_text(r.search.threshold, "{:.5g}"),
        r.search.found() ? fmt::format("{:.5g}-{:.5g}", r.search.lower, r.search.upper)
                         : std::string("-"),
        r.search.found() ? fmt::format("{}, {} ({})", number_text(r.margin, "{:+.3g}"),
                                       number_text(r.lower_margin, "{:+.3g}"), r.lower_outcome)
                         : std::string("-"),
        r.runs_used, r.undecided, r.status);
}

}  // namespace

void add_vcrit(CLI::App& app) {
  auto opt = std::make_shared<VcritCommandOptions>();
  auto* sub = app.add_subcommand(
      "vcrit",
      "Critical velocity per particle size by bisection over the impact speed (thesis §5.2.2; "
      "docs/studies.md)");
  add_impact_case_options(*sub, opt->impact, [&] {
    sub->add_option("--diameters", opt->diameters, "Particle diameters, e.g. 14,18,22,26,30um")
        ->required();
  });
  sub->add_option("--vmin", opt->vmin, "Lowest speed of the search")->capture_default_str();
  sub->add_option("--vmax", opt->vmax, "Highest speed of the search")->capture_default_str();
  sub->add_option("--tol", opt->tol, "Width of the final bracket")->capture_default_str();
  sub->add_option("--max-runs", opt->max_runs, "Impacts per diameter at most")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  sub->add_option("--set", opt->sets, "Override a key in every case: KEY=VALUE (repeatable)");
  sub->add_option("--out", opt->out_dir, "Output folder (default out/vcrit-MATERIAL)")
      ->check(given_path());
  sub->add_option("--jobs", opt->jobs, "Diameters searched at once (default 1)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads-per-job", opt->threads_per_job,
                  "OpenMP threads per impact (default: the cores shared among the jobs)")
      ->check(machine_threads());
  sub->add_flag("--quiet", opt->quiet, "No progress line");
  sub->callback([opt, sub] {
    if (const std::string w = calibration_warning(opt->impact); !w.empty()) std::cerr << w << "\n";
    studies::VcritOptions o = vcrit_options(*opt);
    const std::vector<case_file::Override> overrides = parse_overrides(opt->sets);
    const std::string command =
        command_line("coldspray impact", *sub,
                     {"--diameters", "--vmin", "--vmax", "--tol", "--max-runs", "--set", "--out",
                      "--jobs", "--threads-per-job", "--quiet"});
    const studies::ImpactCaseMaker make_case = [&](double diameter, double speed) {
      const setups::GeneratedCase g =
          setups::impact_case(impact_spec(opt->impact, diameter, speed, command));
      return case_file::load_case_text(kSource, g.yaml, g.origins, overrides);
    };

    const studies::MpiSession mpi;
    const auto lock = studies::lock_study_folder(o.out_dir, mpi);
    o.rank = mpi.rank();
    o.ranks = mpi.size();
    std::vector<studies::VcritRow> rows = studies::find_critical_velocities(make_case, o);
    int simulated = 0;
    for (const auto& r : rows) simulated += r.simulated;
    if (mpi.size() > 1) {
      std::cout << fmt::format("vcrit rank {}/{}: {} diameters, {} impacts simulated now\n",
                               mpi.rank(), mpi.size(), rows.size(), simulated);
      mpi.barrier();
      if (mpi.rank() != 0) return;
      o.ranks = 1;  // every run is on disk now: collect all the diameters' results
      o.progress = false;
      rows = studies::find_critical_velocities(make_case, o);
    }
    studies::write_vcrit_csv(o.out_dir / "vcrit.csv", rows);
    studies::write_vcrit_runs_csv(o.out_dir, o.diameters);
    print_vcrit_table(opt->impact.material, o, rows);
    if (const auto fit = studies::fit_vcrit(rows)) {
      studies::write_vcrit_fit(o.out_dir / "vcrit_fit.json", *fit);
      std::cout << fmt::format(
          "fit: vcrit = {:.5g} m/s + {:.4g} m/s/um * d (R^2 {}, {} sizes); {}/vcrit_fit.json\n",
          fit->a, fit->b, number_text(fit->r_squared, "{:.4f}"), fit->n, o.out_dir.string());
    } else {
      std::cout << "fit: needs critical velocities of two sizes or more\n";
    }
    std::cout << fmt::format(
        "{} impacts simulated now; tables {}/vcrit.csv and {}/vcrit_runs.csv; plot with "
        "tools/coldspray_plot.py vcrit {}\n",
        simulated, o.out_dir.string(), o.out_dir.string(), o.out_dir.string());
  });
}

}  // namespace coldspray::cli
