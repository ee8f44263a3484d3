#include "studies/critical_velocity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/output_schema.hpp"
#include "studies/case_runner.hpp"

namespace coldspray::studies {

namespace fs = std::filesystem;

namespace {

constexpr double kUm = 1e-6;

// A run whose summary is not "ok": the search cannot go on, its outcome is unknown.
class FailedRun : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string label(double x) { return fmt::format("{:.6g}", x); }

double number_or_nan(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>()
                                                                : std::nan("");
}

const nlohmann::json& particle(const nlohmann::json& s) {
  static const nlohmann::json none;
  if (!s.is_object() || !s.contains("bodies") || !s["bodies"].contains("particle")) return none;
  return s["bodies"]["particle"];
}

// The system's verdict in a summary: bonded, rebounded, undecided, or empty when it has none.
std::string outcome(const nlohmann::json& s) {
  if (!s.is_object() || !s.contains("system") || !s["system"].contains("outcome")) return "";
  const nlohmann::json& o = s["system"]["outcome"];
  return o.is_string() ? o.get<std::string>() : "";
}

// The particle's verdict's margin, m/s.
double margin(const nlohmann::json& s) {
  const nlohmann::json& p = particle(s);
  return p.is_object() && p.contains("verdict") ? number_or_nan(p["verdict"], "margin")
                                                : std::nan("");
}

// The particle's largest penetration (bodies/penetration.hpp), NaN without one.
double penetration(const nlohmann::json& s) { return number_or_nan(particle(s), "penetration"); }

// The progress line of a search over several diameters: impacts done, the last outcome, and an
// estimate of the time left from the bisection's run count per diameter.
class Progress {
 public:
  Progress(const VcritOptions& o, std::size_t diameters)
      : on_(o.progress),
        per_diameter_(std::min<double>(
            o.max_runs, 2.0 + std::ceil(std::log2(std::max((o.vmax - o.vmin) / o.tol, 1.0))))),
        diameters_(diameters),
        start_(std::chrono::steady_clock::now()) {}

  void impact(double diameter, double speed, const std::string& outcome, bool simulated) {
    if (!on_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++impacts_;
    if (simulated) ++simulated_;
    line(fmt::format("d {} um at {} m/s {}", label(diameter / kUm), label(speed), outcome));
  }

  void diameter_done(int impacts) {
    if (!on_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++settled_;
    settled_impacts_ += static_cast<std::size_t>(impacts);
    line("");
  }

  ~Progress() {
    if (on_ && impacts_ > 0) std::cerr << "\n";
  }

 private:
  void line(const std::string& last) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // The unsettled diameters' impacts still to come, at most per_diameter_ each.
    const double left = std::max(0.0, per_diameter_ * static_cast<double>(diameters_ - settled_) -
                                          static_cast<double>(impacts_ - settled_impacts_));
    const std::string eta =
        simulated_ > 0 ? fmt::format(", ETA ~{:.0f} s", elapsed / simulated_ * left) : "";
    std::cerr << fmt::format("\rvcrit: {}/{} diameters, {} impacts ({} simulated){}{}{}      ",
                             settled_, diameters_, impacts_, simulated_, eta,
                             last.empty() ? "" : "; ", last)
              << std::flush;
  }

  bool on_;
  double per_diameter_;
  std::size_t diameters_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::size_t impacts_ = 0, simulated_ = 0, settled_ = 0, settled_impacts_ = 0;
};

// One diameter's search, its runs in DIR/d<D>um/v<V>ms.
VcritRow search(const ImpactCaseMaker& make_case, const VcritOptions& o, double diameter,
                Progress& progress) {
  VcritRow row;
  row.diameter = diameter;
  auto bonded = [&](double speed) {
    const fs::path folder = impact_folder(o.out_dir, diameter, speed);
    ++row.runs_used;
    const bool simulate = !case_finished(folder);
    if (simulate) {
      run_in_folder(folder, [&] { return make_case(diameter, speed); });
      ++row.simulated;
    }
    const nlohmann::json s = read_summary(folder);
    const std::string status =
        s.is_object() ? s.value("status", std::string("no status")) : "unreadable summary";
    if (status != "ok") throw FailedRun(fmt::format("failed at {} m/s: {}", label(speed), status));
    const std::string verdict = outcome(s);
    if (verdict == "undecided") ++row.undecided;
    progress.impact(diameter, speed, verdict, simulate);
    return verdict == "bonded";
  };
  // Bonding's activation is a penetration that grows steadily with the speed (docs/bonding.md,
  // "Activation"): its margin at the bracket's ends guesses where the verdict turns.
  const double critical = make_case(diameter, o.vmin).bonding.critical_penetration;
  auto guide = [&](double lo, double hi) {
    const double below = penetration(read_summary(impact_folder(o.out_dir, diameter, lo)));
    const double above = penetration(read_summary(impact_folder(o.out_dir, diameter, hi)));
    if (!(critical > 0.0 && below < critical && above > critical)) return std::nan("");
    return lo + (hi - lo) * (critical - below) / (above - below);
  };
  try {
    row.search = find_threshold(bonded, o.vmin, o.vmax, o.tol, o.max_runs, nullptr,
                                ThresholdLimits{o.vmin, o.vmax}, guide);
    row.status = to_string(row.search.status);
  } catch (const FailedRun& e) {
    row.status = e.what();
    return row;
  }
  if (row.search.found()) {
    const nlohmann::json s = read_summary(impact_folder(o.out_dir, diameter, row.search.threshold));
    const nlohmann::json& p = particle(s);
    row.margin = margin(s);
    row.pbcp = number_or_nan(p, "pbcp");
    row.v_rest = number_or_nan(p, "v_rest");
    const nlohmann::json below = read_summary(impact_folder(o.out_dir, diameter, row.search.lower));
    row.lower_margin = margin(below);
    row.lower_outcome = outcome(below);
  }
  return row;
}

}  // namespace

fs::path impact_folder(const fs::path& out_dir, double diameter, double speed) {
  return out_dir / fmt::format("d{}um", label(diameter / kUm)) / fmt::format("v{}ms", label(speed));
}

std::vector<VcritRow> find_critical_velocities(const ImpactCaseMaker& make_case,
                                               const VcritOptions& options) {
  if (!(options.vmin > 0.0 && options.vmin < options.vmax))
    throw std::invalid_argument("vcrit: need 0 < vmin < vmax");
  for (const double d : options.diameters) {
    make_case(d, options.vmin);
    make_case(d, options.vmax);
  }
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < options.diameters.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(options.ranks)) == options.rank)
      mine.push_back(i);
  std::vector<VcritRow> rows(mine.size());
  Progress progress(options, mine.size());
  run_parallel(mine.size(), options.jobs, options.threads_per_job, [&](std::size_t k) {
    rows[k] = search(make_case, options, options.diameters[mine[k]], progress);
    progress.diameter_done(rows[k].runs_used);
  });
  return rows;
}

void write_vcrit_csv(const fs::path& path, const std::vector<VcritRow>& rows) {
  io::write_atomically(path, [&](std::ostream& out) {
    out << "diameter_um,vcrit_ms,lower_ms,margin,lower_margin,lower_outcome,pbcp,v_rest,runs_used,"
           "undecided,status\n";
    for (const VcritRow& r : rows)
      out << csv_number(r.diameter / kUm) << "," << csv_number(r.search.threshold) << ","
          << csv_number(r.search.lower) << "," << csv_number(r.margin) << ","
          << csv_number(r.lower_margin) << "," << csv_field(r.lower_outcome) << ","
          << csv_number(r.pbcp) << "," << csv_number(r.v_rest) << "," << r.runs_used << ","
          << r.undecided << "," << csv_field(r.status) << "\n";
  });
}

void write_vcrit_runs_csv(const fs::path& out_dir, const std::vector<double>& diameters) {
  io::write_atomically(out_dir / "vcrit_runs.csv", [&](std::ostream& out) {
    out << "diameter_um,velocity_ms,status,outcome,bonded,separation_speed,margin,extensions,cor,"
           "v_rest,abp,pbcp\n";
    for (const double d : diameters) {
      const fs::path folder = impact_folder(out_dir, d, 1.0).parent_path();
      std::vector<std::pair<double, fs::path>> runs;
      std::error_code ec;
      for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() < 4 || name.front() != 'v' || !name.ends_with("ms")) continue;
        try {
          runs.emplace_back(std::stod(name.substr(1, name.size() - 3)), entry.path());
        } catch (const std::exception&) {
          continue;  // not a run folder
        }
      }
      std::sort(runs.begin(), runs.end());
      for (const auto& [speed, run] : runs) {
        if (!case_finished(run)) continue;
        const nlohmann::json s = read_summary(run);
        const nlohmann::json& p = particle(s);
        const nlohmann::json verdict =
            p.is_object() && p.contains("verdict") ? p["verdict"] : nlohmann::json();
        const std::string o = outcome(s);
        out << csv_number(d / kUm) << "," << csv_number(speed) << ","
            << csv_field(s.is_object() ? s.value("status", std::string()) : "unreadable") << ","
            << csv_field(o) << "," << (o == "bonded" ? 1 : 0) << ","
            << csv_number(number_or_nan(verdict, "separation_speed")) << ","
            << csv_number(number_or_nan(verdict, "margin")) << ","
            << csv_number(s.contains("system") ? number_or_nan(s["system"], "extensions")
                                               : std::nan(""))
            << "," << csv_number(number_or_nan(p, "cor")) << ","
            << csv_number(number_or_nan(p, "v_rest")) << "," << csv_number(number_or_nan(p, "abp"))
            << "," << csv_number(number_or_nan(p, "pbcp")) << "\n";
      }
    }
  });
}

std::optional<LinearFit> fit_vcrit(const std::vector<VcritRow>& rows) {
  std::vector<double> d, v;
  for (const VcritRow& r : rows)
    if (r.search.found()) {
      d.push_back(r.diameter / kUm);
      v.push_back(r.search.threshold);
    }
  if (d.size() < 2 || std::adjacent_find(d.begin(), d.end(), std::not_equal_to<>()) == d.end())
    return std::nullopt;
  return fit_line(d, v);
}

namespace {

using Json = nlohmann::ordered_json;

// The line's coefficients' units, d in um and vcrit in m/s: in the fields' declaration and in
// the file's own "units".
constexpr const char* kInterceptUnit = "m/s";
constexpr const char* kSlopeUnit = "m/s/um";

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(); }

// In the order vcrit_fit.json has always had, alphabetical (it was written from nlohmann::json's
// sorted map).
const io::OutputFields<LinearFit>& vcrit_fit_fields() {
  static const io::OutputFields<LinearFit> fields = {
      {"a", kInterceptUnit, [](const auto& f) { return Json(f.a); }},
      {"b", kSlopeUnit, [](const auto& f) { return Json(f.b); }},
      {"model", "-", [](const auto&) { return Json("vcrit = a + b d"); }},
      {"n", "-", [](const auto& f) { return Json(f.n); }},
      {"r_squared", "-", [](const auto& f) { return finite_or_null(f.r_squared); }},
      {"se_a", kInterceptUnit, [](const auto& f) { return finite_or_null(f.se_a); }},
      {"se_b", kSlopeUnit, [](const auto& f) { return finite_or_null(f.se_b); }},
      {"units", "-", [](const auto&) {
         return Json{{"a", kInterceptUnit}, {"b", kSlopeUnit}, {"d", "um"}, {"vcrit", "m/s"}};
       }}};
  return fields;
}

}  // namespace

void write_vcrit_fit(const fs::path& path, const LinearFit& fit) {
  io::write_fields_file(path, vcrit_fit_fields(), fit);
}

io::FieldUnits vcrit_fit_field_units() { return io::field_units(vcrit_fit_fields()); }

}  // namespace coldspray::studies
