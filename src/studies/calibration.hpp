// Calibration of a bonding model's two parameters (G_c and Gdot_c of the energy model, eps_c and
// its rate of the strain model) after mpm-bonding-thesis.md §4.1.2 and §5.1.1-5.1.3: every
// (size, x1, x2) of a parameter grid is simulated; each run is classified bonded (y = 1) by its
// verdict, or by the thesis' tolerances on its restitution ratio and PBCP or ABP (eqs 4.8-4.9,
// §5.1.2); a second-order logistic regression per size (eqs 4.10-4.14) gives the boundary Z = 0
// in the (x1, x2) plane; the crossing of two sizes' boundaries is the calibration (Figs 4.4,
// 5.1-5.3, 5.5). Several grid configurations may be calibrated side by side (discretisation
// sensitivity, Fig 5.7).
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "studies/decision_boundary.hpp"
#include "studies/logistic_regression.hpp"

namespace coldspray::studies {

// How a run is classified. By default by its verdict (docs/bonding.md, "The verdict"): bonded,
// y = 1; rebounded, y = 0; undecided, left out of the regression (and counted). Or by the thesis'
// tolerances (eqs 4.8-4.9, §5.1.2): y = 1 when its restitution ratio is at most cor_max and its
// PBCP (eq 5.1) or its average bond parameter (ABP, eq 4.8) at least the minimum; 0 otherwise,
// also when a measure is undefined (NaN).
struct Classification {
  enum class By { Verdict, CorPbcp, CorAbp };
  By by = By::Verdict;
  double cor_max = 0.003;  // with CorPbcp and CorAbp
  double pbcp_min = 5.0;   // %, with CorPbcp
  double abp_min = 0.15;   // with CorAbp
};

// What a run's summary says of its particle.
struct RunMeasures {
  std::string outcome;  // its verdict: bonded, rebounded, undecided; empty if it has none
  double cor = NAN, abp = NAN, pbcp = NAN;
};

// y = 1 or 0, or kLeftOut: by the verdict, for a run undecided or without a verdict.
inline constexpr int kLeftOut = -1;
int classify(const Classification& rule, const RunMeasures& m);
std::string describe(const Classification& rule);  // "cor <= 0.003 and pbcp >= 5 %"

// One parameter's values: `count` from `from` to `to` (both included), equally spaced in x or,
// with log spacing, in log10 x (from, to > 0). count 1 gives `from`.
struct ParameterAxis {
  std::string key;   // the bonding key, e.g. critical_energy
  std::string unit;  // its SI unit, e.g. J/m^2
  double from = 0.0;
  double to = 0.0;
  int count = 2;
  bool log = false;
};
std::vector<double> parameter_values(const ParameterAxis& axis);

struct CalibrationSize {
  double diameter = 0.0;  // m
  double velocity = 0.0;  // m/s: the size's experimental critical velocity
  Classification classify;
  std::string label() const;  // "14um": the size's name in files
};

struct CalibrationPlan {
  std::vector<std::string> grids;  // grid configurations, as written ("0.7um/0.175um")
  std::vector<CalibrationSize> sizes;
  ParameterAxis x1, x2;
  LogisticOptions fit;
};

// One impact of the plan and its folder, DIR/<grid>/<size>-v<V>ms/p<x1>_<x2> (SI values).
struct CalibrationRun {
  std::size_t grid = 0, size = 0;
  double x1 = 0.0, x2 = 0.0;
  std::filesystem::path folder;
};
std::vector<CalibrationRun> calibration_runs(const CalibrationPlan& plan,
                                             const std::filesystem::path& out_dir);
// "0.7um-0.175um": a grid's name in folders and files.
std::string grid_label(const std::string& grid);

using CalibrationCaseMaker = std::function<case_file::Case(const CalibrationRun&)>;

struct CalibrationRunOptions {
  std::filesystem::path out_dir;
  int jobs = 1;
  int threads_per_job = 0;
  bool progress = true;
  int rank = 0;  // runs i % ranks == rank
  int ranks = 1;
};

struct CalibrationCounts {
  std::size_t runs = 0, skipped = 0, ran = 0, failed = 0;  // as SweepCounts
};

// Makes the study's output folder and returns the indices of `folders` this rank still has to
// run, counting the study's runs and those already finished in `counts`.
std::vector<std::size_t> pending_runs(const std::vector<std::filesystem::path>& folders,
                                      const CalibrationRunOptions& options,
                                      CalibrationCounts& counts);

// Runs this rank's unfinished impacts (resumable, parallel, failures recorded; as a sweep).
// Every (grid, size) case is loaded first at two corners of the parameter rectangle, so that bad
// input stops the study before anything runs.
CalibrationCounts run_calibration(const CalibrationPlan& plan,
                                  const CalibrationCaseMaker& make_case,
                                  const CalibrationRunOptions& options);

// The analysis of one size on one grid.
struct SizeResult {
  // failed: no usable summary (or, classified by the verdict, a summary without one); undecided:
  // left out of the fit, classified by the verdict
  std::size_t runs = 0, bonded = 0, not_bonded = 0, undecided = 0, failed = 0;
  std::optional<LogisticFit> fit;
  std::string diagnosis;  // why there is no fit, else empty
  std::string boundary_file;
  std::size_t boundary_curves = 0;
};

struct GridResult {
  std::string grid;
  std::vector<SizeResult> sizes;
  std::vector<std::array<double, 2>> intersections;  // of the first two sizes' boundaries
  // The crossing nearest the rectangle's centre; when the boundaries do not cross, the midpoint
  // of their closest approach, a compromise that says so in `diagnosis` (docs/studies-math.md).
  std::optional<std::array<double, 2>> calibrated;
  std::optional<ClosestApproach> closest;  // of the two boundaries, when both exist
  std::string diagnosis;                   // why there is no crossing, else empty
};

// Reads the runs on disk, classifies, fits, traces and intersects; writes DIR/runs.csv,
// DIR/boundary_<size>.csv (boundary_<grid>_<size>.csv with several grids) and
// DIR/calibration.json. Does not throw for a failed fit or no intersection: they are diagnosed.
std::vector<GridResult> analyse_calibration(const CalibrationPlan& plan,
                                            const std::filesystem::path& out_dir,
                                            const std::string& name);

}  // namespace coldspray::studies
