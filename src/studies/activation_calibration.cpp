#include "studies/activation_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "studies/calibration_json.hpp"
#include "studies/case_runner.hpp"

namespace coldspray::studies {

namespace fs = std::filesystem;

std::vector<ActivationRun> activation_runs(const ActivationPlan& plan, const fs::path& out_dir) {
  std::vector<ActivationRun> runs;
  for (std::size_t g = 0; g < plan.grids.size(); ++g)
    for (std::size_t s = 0; s < plan.sizes.size(); ++s)
      for (const double factor : {1.0 - plan.step, 1.0 + plan.step}) {
        const double speed = factor * plan.sizes[s].velocity;
        runs.push_back({g, s, speed,
                        out_dir / grid_label(plan.grids[g]) /
                            fmt::format("{}-v{:.6g}ms", plan.sizes[s].label(), speed)});
      }
  return runs;
}

CalibrationCounts run_activation_calibration(const ActivationPlan& plan,
                                             const ActivationCaseMaker& make_case,
                                             const CalibrationRunOptions& options) {
  const std::vector<ActivationRun> runs = activation_runs(plan, options.out_dir);
  for (const ActivationRun& run : runs) make_case(run);
  CalibrationCounts counts;
  std::vector<fs::path> folders;
  for (const ActivationRun& run : runs) folders.push_back(run.folder);
  const std::vector<std::size_t> pending = pending_runs(folders, options, counts);
  std::mutex tally;
  run_parallel(pending.size(), options.jobs, options.threads_per_job, [&](std::size_t k) {
    const ActivationRun& run = runs[pending[k]];
    const bool ok = run_in_folder(run.folder, [&] { return make_case(run); });
    const std::lock_guard<std::mutex> lock(tally);
    ++counts.ran;
    if (!ok) ++counts.failed;
  });
  return counts;
}

PenetrationLaw penetration_law(double v_c, double v1, double p1, double v2, double p2) {
  if (!(p1 > 0.0 && p2 > 0.0 && v1 > 0.0 && v2 > 0.0 && v1 != v2)) return {};
  const double b = std::log(p2 / p1) / std::log(v2 / v1);
  return {p1 * std::pow(v_c / v1, b), b};
}

double predicted_vcrit(const PenetrationLaw& law, double v_c, double critical) {
  return v_c * std::pow(critical / law.at_velocity, 1.0 / law.exponent);
}

double minimax_critical_penetration(const std::vector<PenetrationLaw>& laws) {
  double lo = std::log(laws.front().at_velocity), hi = lo;
  for (const PenetrationLaw& l : laws) {
    lo = std::min(lo, std::log(l.at_velocity));
    hi = std::max(hi, std::log(l.at_velocity));
  }
  // Largest plus smallest error: <= 0 at the lowest ln p_c, >= 0 at the highest, rising.
  auto balance = [&](double x) {
    double most = -INFINITY, least = INFINITY;
    for (const PenetrationLaw& l : laws) {
      const double e = (x - std::log(l.at_velocity)) / l.exponent;
      most = std::max(most, e), least = std::min(least, e);
    }
    return most + least;
  };
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (balance(mid) > 0.0 ? hi : lo) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

namespace {

// A run's largest penetration, NaN unless it finished and its compression ended.
double measured_penetration(const fs::path& folder, std::string& status) {
  const nlohmann::json s = read_summary(folder);
  status = s.is_object() ? s.value("status", std::string("no status")) : "missing";
  if (status != "ok" || !s.contains("bodies") || !s["bodies"].contains("particle")) return NAN;
  const nlohmann::json& p = s["bodies"]["particle"];
  if (!p.contains("penetration_peak_time") || !p["penetration_peak_time"].is_number()) {
    status = "compression not ended";
    return NAN;
  }
  return p.value("penetration", NAN);
}

}  // namespace

std::vector<ActivationGridResult> analyse_activation(const ActivationPlan& plan,
                                                     const fs::path& out_dir,
                                                     const std::string& name) {
  const std::vector<ActivationRun> runs = activation_runs(plan, out_dir);
  std::vector<double> penetration(runs.size());
  io::write_atomically(out_dir / "runs.csv", [&](std::ostream& out) {
    out << "grid,size,diameter_um,velocity_ms,status,penetration\n";
    for (std::size_t k = 0; k < runs.size(); ++k) {
      std::string status;
      penetration[k] = measured_penetration(runs[k].folder, status);
      const CalibrationSize& size = plan.sizes[runs[k].size];
      out << csv_field(plan.grids[runs[k].grid]) << "," << size.label() << ","
          << csv_number(size.diameter * 1e6) << "," << csv_number(runs[k].speed) << ","
          << csv_field(status) << "," << csv_number(penetration[k]) << "\n";
    }
  });
  std::vector<ActivationGridResult> results(plan.grids.size());
  for (std::size_t g = 0; g < plan.grids.size(); ++g) {
    ActivationGridResult& r = results[g];
    r.grid = plan.grids[g];
    for (std::size_t s = 0; s < plan.sizes.size(); ++s) {
      const std::size_t k = 2 * (g * plan.sizes.size() + s);  // activation_runs' order
      r.laws.push_back(penetration_law(plan.sizes[s].velocity, runs[k].speed, penetration[k],
                                       runs[k + 1].speed, penetration[k + 1]));
      if (!r.laws.back().usable() && r.diagnosis.empty())
        r.diagnosis = fmt::format("size {}: no rising penetration between its two runs (runs.csv)",
                                  plan.sizes[s].label());
    }
    if (r.diagnosis.empty()) {
      r.critical_penetration = minimax_critical_penetration(r.laws);
      for (std::size_t s = 0; s < plan.sizes.size(); ++s)
        r.predicted.push_back(
            predicted_vcrit(r.laws[s], plan.sizes[s].velocity, *r.critical_penetration));
    }
  }
  write_activation_json(plan, results, out_dir, name);
  return results;
}

}  // namespace coldspray::studies
