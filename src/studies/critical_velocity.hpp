// The critical velocity of each particle size: the lowest impact speed at which the particle
// bonds, found by bisection over the speed with one impact simulation per evaluation
// (mpm-bonding-thesis.md §5.2.2, Table 5.4, Figs 5.13-5.14), and the line vcrit = a + b d
// through them. Every impact runs in its own folder DIR/d<D>um/v<V>ms, reused when finished, so
// an interrupted or repeated search costs nothing for the speeds already simulated.
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "io/output_schema.hpp"
#include "studies/bisection.hpp"
#include "studies/linear_fit.hpp"

namespace coldspray::studies {

// The case of one impact of a particle of `diameter` (m) at `speed` (m/s); InputError on bad
// input.
using ImpactCaseMaker = std::function<case_file::Case(double diameter, double speed)>;

struct VcritOptions {
  std::filesystem::path out_dir;
  std::vector<double> diameters;  // m
  double vmin = 500.0;            // m/s: the search's bracket; no speed outside it is tried
  double vmax = 1200.0;
  double tol = 2.0;   // m/s: final bracket width
  int max_runs = 16;  // predicate evaluations per diameter
  int jobs = 1;       // diameters searched at once in this process (each search is sequential)
  int threads_per_job = 0;
  int rank = 0;  // this process searches the diameters i % ranks == rank
  int ranks = 1;
  bool progress = false;  // a progress line on stderr after every impact
};

struct VcritRow {
  double diameter = 0.0;  // m
  ThresholdResult search;
  std::string status;  // found, not bracketed, evaluation limit, non-monotone, or a run's failure
  // The verdict's margins (docs/bonding.md) of the runs at vcrit and at the highest speed that did
  // not bond, m/s, and that run's outcome (rebounded, or undecided: counted as not bonded).
  double margin = std::numeric_limits<double>::quiet_NaN();
  double lower_margin = std::numeric_limits<double>::quiet_NaN();
  std::string lower_outcome;
  double pbcp = std::numeric_limits<double>::quiet_NaN();    // %, of the run at vcrit
  double v_rest = std::numeric_limits<double>::quiet_NaN();  // m/s, of the run at vcrit
  int runs_used = 0;                                         // distinct speeds the search used
  int undecided = 0;  // of those, undecided (counted as not bonded)
  int simulated = 0;  // of those, simulated now (the others were on disk)
};

// DIR/d<D>um/v<V>ms for a diameter in m and a speed in m/s, both to 6 significant digits.
std::filesystem::path impact_folder(const std::filesystem::path& out_dir, double diameter,
                                    double speed);

// Searches this rank's diameters (find_threshold over [vmin, vmax], predicate "the impact's
// summary says system.bonded", its verdict; an undecided run counts as not bonded). A run that
// fails (fault, input error) stops its diameter's search
// with the failure as status; the others go on. Every case is loaded before anything runs, at
// vmin and vmax, so that bad input stops the study first (InputError).
std::vector<VcritRow> find_critical_velocities(const ImpactCaseMaker& make_case,
                                               const VcritOptions& options);

// DIR/vcrit.csv: diameter_um, vcrit_ms, lower_ms, margin, lower_margin, lower_outcome, pbcp,
// v_rest, runs_used, undecided, status.
void write_vcrit_csv(const std::filesystem::path& path, const std::vector<VcritRow>& rows);

// DIR/vcrit_runs.csv: every finished impact folder of the given diameters (diameter_um,
// velocity_ms, status, outcome, bonded, separation_speed, margin, extensions, cor, v_rest, abp,
// pbcp), by diameter and speed.
void write_vcrit_runs_csv(const std::filesystem::path& out_dir,
                          const std::vector<double>& diameters);

// vcrit = a + b d over the diameters whose search found a threshold, d in um and vcrit in m/s;
// nullopt with fewer than two.
std::optional<LinearFit> fit_vcrit(const std::vector<VcritRow>& rows);
// The fit as JSON (vcrit_fit.json): a, b, r_squared, se_a, se_b, n, and the units.
void write_vcrit_fit(const std::filesystem::path& path, const LinearFit& fit);

// vcrit_fit.json's fields with their units, in written order: docs/outputs.md's table lists the
// same (tests/run/output_fields_test.cpp).
io::FieldUnits vcrit_fit_field_units();

}  // namespace coldspray::studies
