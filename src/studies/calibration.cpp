#include "studies/calibration.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "run/bond_family.hpp"
#include "studies/calibration_json.hpp"
#include "studies/case_runner.hpp"
#include "studies/decision_boundary.hpp"
#include "studies/task_pool.hpp"

namespace coldspray::studies {

namespace fs = std::filesystem;

int classify(const Classification& rule, const RunMeasures& m) {
  if (rule.by == Classification::By::Verdict)
    return m.outcome == "bonded" ? 1 : m.outcome == "rebounded" ? 0 : kLeftOut;
  // Eqs 4.8-4.9: y = 1 for CoR <= tol & ABP >= tol; §5.1.2 puts PBCP in ABP's place. A NaN
  // fails every comparison, so an undefined measure classifies as not bonded.
  const bool bond =
      rule.by == Classification::By::CorPbcp ? m.pbcp >= rule.pbcp_min : m.abp >= rule.abp_min;
  return m.cor <= rule.cor_max && bond ? 1 : 0;
}

std::string describe(const Classification& rule) {
  switch (rule.by) {
    case Classification::By::CorPbcp:
      return fmt::format("cor <= {:.6g} and pbcp >= {:.6g} %", rule.cor_max, rule.pbcp_min);
    case Classification::By::CorAbp:
      return fmt::format("cor <= {:.6g} and abp >= {:.6g}", rule.cor_max, rule.abp_min);
    case Classification::By::Verdict:
      break;
  }
  return "by the runs' verdicts";
}

std::vector<double> parameter_values(const ParameterAxis& axis) {
  if (axis.count < 1) throw std::invalid_argument("parameter axis: count must be >= 1");
  if (axis.log && !(axis.from > 0.0 && axis.to > 0.0))
    throw std::invalid_argument("parameter axis: log spacing needs from, to > 0");
  if (axis.count == 1) return {axis.from};
  const double a = axis.log ? std::log10(axis.from) : axis.from;
  const double b = axis.log ? std::log10(axis.to) : axis.to;
  std::vector<double> values;
  for (int i = 0; i < axis.count; ++i) {
    // The ends exactly as given; the others counted from them, not accumulated.
    const double t = a + (b - a) * i / (axis.count - 1);
    values.push_back(i == 0                ? axis.from
                     : i == axis.count - 1 ? axis.to
                     : axis.log            ? std::pow(10.0, t)
                                           : t);
  }
  return values;
}

std::string CalibrationSize::label() const { return fmt::format("{:.6g}um", diameter * 1e6); }

std::string grid_label(const std::string& grid) {
  std::string label;
  for (const char ch : grid)
    if (ch != ' ') label += ch == '/' ? '-' : ch;
  return label;
}

std::vector<CalibrationRun> calibration_runs(const CalibrationPlan& plan, const fs::path& out_dir) {
  const std::vector<double> v1 = parameter_values(plan.x1), v2 = parameter_values(plan.x2);
  std::vector<CalibrationRun> runs;
  for (std::size_t g = 0; g < plan.grids.size(); ++g)
    for (std::size_t s = 0; s < plan.sizes.size(); ++s)
      for (const double x1 : v1)
        for (const double x2 : v2)
          runs.push_back(
              {g, s, x1, x2,
               out_dir / grid_label(plan.grids[g]) /
                   fmt::format("{}-v{:.6g}ms", plan.sizes[s].label(), plan.sizes[s].velocity) /
                   fmt::format("p{:.6g}_{:.6g}", x1, x2)});
  return runs;
}

std::vector<std::size_t> pending_runs(const std::vector<fs::path>& folders,
                                      const CalibrationRunOptions& options,
                                      CalibrationCounts& counts) {
  io::make_output_folder(options.out_dir);  // InputError if it is a file, under one, unwritable
  counts.runs = folders.size();
  return pending_folders(folders, options.rank, options.ranks, counts.skipped);
}

CalibrationCounts run_calibration(const CalibrationPlan& plan,
                                  const CalibrationCaseMaker& make_case,
                                  const CalibrationRunOptions& options) {
  const std::vector<CalibrationRun> runs = calibration_runs(plan, options.out_dir);
  for (std::size_t g = 0; g < plan.grids.size(); ++g)
    for (std::size_t s = 0; s < plan.sizes.size(); ++s) {
      make_case({g, s, plan.x1.from, plan.x2.from, {}});
      make_case({g, s, plan.x1.to, plan.x2.to, {}});
    }
  CalibrationCounts counts;
  std::vector<fs::path> folders;
  for (const CalibrationRun& run : runs) folders.push_back(run.folder);
  const std::vector<std::size_t> pending = pending_runs(folders, options, counts);
  std::size_t done = 0, failed = 0;
  std::mutex report;
  const auto start = std::chrono::steady_clock::now();
  auto finished = [&](std::size_t r, const std::exception_ptr& failure) {
    bool ok = false;
    try {
      ok = record_outcome(runs[r].folder, failure);
    } catch (...) {  // not even the failure could be written: the run stays pending on disk
    }
    const std::lock_guard<std::mutex> lock(report);
    ++done;
    if (!ok) ++failed;
    if (!options.progress) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << fmt::format("\rcalibrate: {}/{} run, {} failed, {} skipped, ETA {:.0f} s   ", done,
                             pending.size(), failed, counts.skipped,
                             elapsed / done * (pending.size() - done))
              << std::flush;
  };

  // The runs of one grid and size differ only in the bonding parameters: each such group is one
  // bond family (run/bond_family.hpp), whose members share their trajectory until they bond. A
  // family queues its branches for any free job or, once twice as many tasks wait as there are
  // jobs (a branch holds a copy of the state), runs them itself.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> families;
  for (const std::size_t r : pending) families[{runs[r].grid, runs[r].size}].push_back(r);
  TaskPool pool(options.jobs, options.threads_per_job);
  for (const auto& [key, family] : families)
    pool.submit([&, family = family] {
      std::vector<run::FamilyMember> members;
      std::vector<std::size_t> member_run;
      for (const std::size_t r : family) {
        std::exception_ptr failure;
        try {
          fs::remove_all(runs[r].folder);
          fs::create_directories(runs[r].folder);
          members.push_back({make_case(runs[r]), runs[r].folder});
          member_run.push_back(r);
          continue;
        } catch (...) {
          failure = std::current_exception();
        }
        finished(r, failure);
      }
      run::FamilyHooks hooks;
      hooks.spawn = [&pool](std::function<void()> branch) {
        if (pool.queued() >= 2 * static_cast<std::size_t>(pool.jobs()))
          branch();
        else
          pool.submit(std::move(branch));
      };
      hooks.finished = [&finished, member_run](std::size_t m, const std::exception_ptr& failure) {
        finished(member_run[m], failure);
      };
      try {
        run::run_bond_family(members, hooks);
      } catch (const std::invalid_argument&) {  // not one family: a defect of make_case
        for (const std::size_t r : member_run) finished(r, std::current_exception());
      }
    });
  pool.run();
  throw_if_interrupted();
  counts.ran = done;
  counts.failed = failed;
  return counts;
}

namespace {

struct Measured {
  std::string status = "pending";
  RunMeasures run;
  double v_rest = NAN, separation_speed = NAN, margin = NAN;
  bool usable = false;  // ok, with the particle's measures
};

Measured measure(const fs::path& folder) {
  Measured m;
  if (!case_finished(folder)) return m;
  const nlohmann::json s = read_summary(folder);
  if (!s.is_object()) {
    m.status = "unreadable summary";
    return m;
  }
  m.status = s.value("status", std::string("no status"));
  if (m.status != "ok" || !s.contains("bodies") || !s["bodies"].contains("particle")) return m;
  const nlohmann::json& p = s["bodies"]["particle"];
  const nlohmann::json verdict = p.value("verdict", nlohmann::json::object());
  auto get = [](const nlohmann::json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
  };
  m.run.outcome = verdict.value("outcome", std::string());
  m.run.cor = get(p, "cor");
  m.run.abp = get(p, "abp");
  m.run.pbcp = get(p, "pbcp");
  m.v_rest = get(p, "v_rest");
  m.separation_speed = get(verdict, "separation_speed");
  m.margin = get(verdict, "margin");
  m.usable = true;
  return m;
}

// The parameter rectangle [lo1, hi1] x [lo2, hi2] of the plan's two axes.
struct Rectangle {
  double lo1, hi1, lo2, hi2;
};

Rectangle parameter_rectangle(const CalibrationPlan& plan) {
  return {std::min(plan.x1.from, plan.x1.to), std::max(plan.x1.from, plan.x1.to),
          std::min(plan.x2.from, plan.x2.to), std::max(plan.x2.from, plan.x2.to)};
}

using SamplesBySize = std::vector<std::vector<std::vector<Sample>>>;  // [grid][size]

// Classify: each run's result bonded (1), not bonded (0) or left out, counted per grid and size,
// its samples gathered for the fit and its row written to runs.csv.
void classify_runs(const CalibrationPlan& plan, const fs::path& out_dir,
                   std::vector<GridResult>& results, SamplesBySize& samples) {
  const std::vector<CalibrationRun> runs = calibration_runs(plan, out_dir);
  io::write_atomically(out_dir / "runs.csv", [&](std::ostream& out) {
    out << "grid,size,diameter_um,velocity_ms," << plan.x1.key << "," << plan.x2.key
        << ",status,outcome,separation_speed,margin,cor,abp,pbcp,v_rest,y\n";
    for (const CalibrationRun& run : runs) {
      const CalibrationSize& size = plan.sizes[run.size];
      const Measured m = measure(run.folder);
      SizeResult& r = results[run.grid].sizes[run.size];
      ++r.runs;
      const int y = m.usable ? classify(size.classify, m.run) : kLeftOut;
      if (y != kLeftOut) {
        ++(y == 1 ? r.bonded : r.not_bonded);
        samples[run.grid][run.size].push_back({run.x1, run.x2, y});
      } else {
        ++(m.usable && m.run.outcome == "undecided" ? r.undecided : r.failed);
      }
      out << csv_field(plan.grids[run.grid]) << "," << size.label() << ","
          << csv_number(size.diameter * 1e6) << "," << csv_number(size.velocity) << ","
          << csv_number(run.x1) << "," << csv_number(run.x2) << "," << csv_field(m.status) << ","
          << csv_field(m.run.outcome) << "," << csv_number(m.separation_speed) << ","
          << csv_number(m.margin) << "," << csv_number(m.run.cor) << "," << csv_number(m.run.abp)
          << "," << csv_number(m.run.pbcp) << "," << csv_number(m.v_rest) << ","
          << (y == kLeftOut ? std::string("") : std::to_string(y)) << "\n";
    }
  });
}

// Fit: one size's logistic regression and its decision boundary Z = 0 in the rectangle, written
// to its boundary CSV; a size with one class only, or whose fit fails, gets its diagnosis.
void fit_size(const CalibrationPlan& plan, std::size_t g, std::size_t s,
              const std::vector<Sample>& size_samples, const Rectangle& box,
              const fs::path& out_dir, SizeResult& r, Boundary& boundary) {
  if (r.bonded == 0 || r.not_bonded == 0) {
    const bool by_verdict = plan.sizes[s].classify.by == Classification::By::Verdict;
    r.diagnosis = fmt::format(
        "one class only ({} bonded, {} not bonded{}{}): no boundary; widen the parameter "
        "rectangle or {} ({})",
        r.bonded, r.not_bonded, r.undecided ? fmt::format(", {} undecided", r.undecided) : "",
        r.failed ? fmt::format(", {} failed", r.failed) : "",
        by_verdict ? "let undecided runs go on longer (end_time, metrics.verdict_extensions)"
                   : "adjust the tolerances",
        describe(plan.sizes[s].classify));
    return;
  }
  try {
    r.fit = fit_logistic(size_samples, plan.fit);
    boundary = decision_boundary(*r.fit, box.lo1, box.hi1, box.lo2, box.hi2);
  } catch (const std::exception& e) {
    r.fit.reset();
    r.diagnosis = std::string("fit failed: ") + e.what();
    return;
  }
  r.boundary_curves = boundary.curves.size();
  r.boundary_file =
      plan.grids.size() == 1
          ? fmt::format("boundary_{}.csv", plan.sizes[s].label())
          : fmt::format("boundary_{}_{}.csv", grid_label(plan.grids[g]), plan.sizes[s].label());
  write_boundary_csv(out_dir / r.boundary_file, boundary);
  if (r.boundary_curves == 0)
    r.diagnosis = "the boundary Z = 0 does not cross the parameter rectangle";
}

// Intersect: the calibrated pair where the two sizes' boundaries cross nearest the rectangle's
// centre, or else the midpoint of their closest approach.
void intersect_sizes(const CalibrationPlan& plan, const std::vector<Boundary>& boundaries,
                     const Rectangle& box, GridResult& gr) {
  if (plan.sizes.size() < 2) {
    gr.diagnosis = "one size: no second boundary to intersect";
    return;
  }
  if (!gr.sizes[0].fit || !gr.sizes[1].fit || gr.sizes[0].boundary_curves == 0 ||
      gr.sizes[1].boundary_curves == 0) {
    gr.diagnosis = "no intersection: a size has no boundary in the rectangle (see its diagnosis)";
    return;
  }
  const std::vector<Intersection> points = intersect_boundaries(boundaries[0], boundaries[1]);
  for (const Intersection& p : points) gr.intersections.push_back({p.point[0], p.point[1]});
  const PlaneGrid& frame = boundaries[0].grid;
  const Eigen::Vector2d centre = frame.from_plot(
      0.5 * (frame.to_plot({box.lo1, box.lo2}) + frame.to_plot({box.hi1, box.hi2})));
  gr.closest = closest_approach(boundaries[0].curves, boundaries[1].curves, frame);
  if (const auto nearest = nearest_intersection(points, centre, frame)) {
    gr.calibrated = std::array<double, 2>{nearest->point[0], nearest->point[1]};
  } else if (gr.closest) {
    gr.calibrated = std::array<double, 2>{gr.closest->midpoint[0], gr.closest->midpoint[1]};
    gr.diagnosis = fmt::format(
        "no intersection: the two sizes' boundaries do not cross inside the parameter "
        "rectangle; they come within {:.3g} of its width, and the calibrated pair is the "
        "midpoint of that closest approach, a compromise",
        gr.closest->distance);
  }
}

}  // namespace

std::vector<GridResult> analyse_calibration(const CalibrationPlan& plan, const fs::path& out_dir,
                                            const std::string& name) {
  std::vector<GridResult> results(plan.grids.size());
  SamplesBySize samples(plan.grids.size(), std::vector<std::vector<Sample>>(plan.sizes.size()));
  for (std::size_t g = 0; g < plan.grids.size(); ++g) {
    results[g].grid = plan.grids[g];
    results[g].sizes.resize(plan.sizes.size());
  }
  classify_runs(plan, out_dir, results, samples);
  const Rectangle box = parameter_rectangle(plan);
  for (std::size_t g = 0; g < plan.grids.size(); ++g) {
    std::vector<Boundary> boundaries(plan.sizes.size());
    for (std::size_t s = 0; s < plan.sizes.size(); ++s)
      fit_size(plan, g, s, samples[g][s], box, out_dir, results[g].sizes[s], boundaries[s]);
    intersect_sizes(plan, boundaries, box, results[g]);
  }
  write_calibration_json(plan, results, out_dir, name);
  return results;
}

}  // namespace coldspray::studies
