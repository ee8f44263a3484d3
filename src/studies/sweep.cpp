#include "studies/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "studies/case_runner.hpp"

namespace coldspray::studies {

namespace fs = std::filesystem;

std::vector<SweepCase> sweep_cases(const std::vector<Variation>& vary) {
  const auto combos = combinations(vary);
  const int width = std::max(4, static_cast<int>(std::to_string(combos.size()).size()));
  std::vector<SweepCase> cases;
  for (std::size_t i = 0; i < combos.size(); ++i)
    cases.push_back({fmt::format("case_{:0{}d}", i + 1, width), combos[i]});
  return cases;
}

namespace {

// Runs one case into its (cleared) folder, with its overrides listed in overrides.txt.
bool run_one(const std::string& case_path, const std::vector<case_file::Override>& base,
             const SweepCase& sc, const fs::path& folder) {
  return run_in_folder(folder, [&] {
    io::write_atomically(folder / "overrides.txt", [&](std::ostream& list) {
      for (const auto& o : sc.overrides) list << o.key << "=" << o.value << "\n";
    });
    std::vector<case_file::Override> overrides = base;
    overrides.insert(overrides.end(), sc.overrides.begin(), sc.overrides.end());
    return case_file::load_case(case_path, overrides);
  });
}

// A summary value as a CSV field: numbers, 1/0 for booleans, text (an outcome) quoted if need
// be; nan for what is absent or null.
std::string value(const nlohmann::json& j) {
  return j.is_number()    ? fmt::format("{:.10g}", j.get<double>())
         : j.is_boolean() ? std::string(j.get<bool>() ? "1" : "0")
         : j.is_string()  ? csv_field(j.get<std::string>())
                          : std::string("nan");
}

// Per body: its measures (bonding.md#metrics), then its verdict's (bonding.md#the-verdict).
constexpr const char* kBodyColumns[] = {"cor",
                                        "v_rest",
                                        "abp",
                                        "pbcp",
                                        "mean_eqps",
                                        "max_temperature",
                                        "plastic_energy_density",
                                        "jetted_fraction",
                                        "crater_depth",
                                        "flattening_ratio"};
constexpr const char* kVerdictColumns[] = {"outcome", "separation_speed", "margin"};
// A pull-off's (docs/pull-off.md), from its summary.json.
constexpr const char* kPullOffColumns[] = {
    "peak_force",      "work_of_separation", "bonded_area", "projected_area",
    "strength_bonded", "strength_projected", "separated"};

const char* const kPullOffFolder = "pull-off";

bool pulled_off(const fs::path& folder) {
  return fs::exists(folder / kPullOffFolder / "summary.json");
}

// Pulls one finished case off into its pull-off/ folder (cleared first: an interrupted pull
// starts over); a failure is written to pull-off-error.txt and the sweep goes on.
void pull_off_case(const fs::path& folder, PullOffOptions o) {
  o.impact = folder;
  o.out = folder / kPullOffFolder;
  o.progress = false;
  fs::remove_all(o.out);
  fs::remove(folder / "pull-off-error.txt");
  try {
    pull_off(o);
  } catch (const std::exception& e) {
    io::write_atomically(folder / "pull-off-error.txt",
                         [&](std::ostream& out) { out << e.what() << "\n"; });
  }
}

}  // namespace

void write_sweep_csv(const fs::path& out_dir, const std::vector<Variation>& vary,
                     const std::vector<SweepCase>& cases) {
  std::vector<nlohmann::json> summaries, pulls;
  std::vector<std::string> bodies;
  bool any_pulled = false;
  for (const SweepCase& sc : cases) {
    const bool pulled = pulled_off(out_dir / sc.folder);
    any_pulled |= pulled;
    pulls.push_back(pulled ? read_summary(out_dir / sc.folder / kPullOffFolder)
                           : nlohmann::json::object());
    summaries.push_back(case_finished(out_dir / sc.folder) ? read_summary(out_dir / sc.folder)
                                                           : nlohmann::json());
    const auto& s = summaries.back();
    if (bodies.empty() && s.is_object() && s.contains("bodies") && !s["bodies"].empty())
      for (const auto& [name, _] : s["bodies"].items()) bodies.push_back(name);
  }
  io::write_atomically(out_dir / "sweep.csv", [&](std::ostream& out) {
    out << "case,status";
    for (const Variation& v : vary) out << "," << csv_field(v.key);
    out << ",steps,time,wall_seconds,energy_error,bonded,outcome";
    for (const auto& b : bodies) {
      for (const char* q : kBodyColumns) out << "," << csv_field(b + "." + q);
      for (const char* q : kVerdictColumns) out << "," << csv_field(b + "." + q);
    }
    if (any_pulled)
      for (const char* q : kPullOffColumns) out << "," << csv_field(std::string("pull_off.") + q);
    out << "\n";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const nlohmann::json& s = summaries[i];
      const bool done = s.is_object() && s.contains("status");
      out << cases[i].folder << ","
          << csv_field(done ? s["status"].get<std::string>() : std::string("pending"));
      for (const auto& o : cases[i].overrides) out << "," << csv_field(o.value);
      auto field = [&](const char* a, const char* b = nullptr) {
        if (!done || !s.contains(a)) return std::string("nan");
        return value(b ? s[a].value(b, nlohmann::json()) : s[a]);
      };
      out << "," << field("steps") << "," << field("time") << "," << field("wall_seconds") << ","
          << field("energy", "relative_error") << "," << field("system", "bonded") << ","
          << field("system", "outcome");
      for (const auto& b : bodies) {
        const bool has = done && s.contains("bodies") && s["bodies"].contains(b);
        const nlohmann::json& body = has ? s["bodies"][b] : nlohmann::json::object();
        const nlohmann::json verdict = body.value("verdict", nlohmann::json::object());
        for (const char* q : kBodyColumns) out << "," << value(body.value(q, nlohmann::json()));
        for (const char* q : kVerdictColumns)
          out << "," << value(verdict.value(q, nlohmann::json()));
      }
      if (any_pulled)
        for (const char* q : kPullOffColumns)
          out << "," << value(pulls[i].value(q, nlohmann::json()));
      out << "\n";
    }
  });
}

void check_sweep_cases(const std::string& case_path, const std::vector<case_file::Override>& base,
                       const std::vector<Variation>& vary) {
  for (const auto& overrides : combinations(vary)) {
    std::vector<case_file::Override> all = base;
    all.insert(all.end(), overrides.begin(), overrides.end());
    case_file::load_case(case_path, all);
  }
}

SweepCounts run_sweep(const std::string& case_path, const std::vector<case_file::Override>& base,
                      const std::vector<Variation>& vary, const SweepOptions& options) {
  check_sweep_cases(case_path, base, vary);  // bad input stops the sweep before anything runs
  const std::vector<SweepCase> cases = sweep_cases(vary);
  io::make_output_folder(options.out_dir);  // InputError if it is a file, under one, unwritable

  SweepCounts counts;
  counts.cases = cases.size();
  std::vector<fs::path> folders;
  for (const SweepCase& sc : cases) folders.push_back(options.out_dir / sc.folder);
  const std::vector<std::size_t> pending =
      pending_folders(folders, options.rank, options.ranks, counts.skipped);

  std::atomic<std::size_t> finished{0}, failed{0};
  std::mutex report;
  const auto start = std::chrono::steady_clock::now();
  auto progress = [&] {
    if (!options.progress) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = finished.load();
    const double eta = done > 0 ? elapsed / done * (pending.size() - done) : 0.0;
    std::cerr << fmt::format("\rsweep{}: {}/{} run, {} failed, {} skipped, ETA {:.0f} s   ",
                             options.ranks > 1 ? fmt::format(" rank {}", options.rank) : "", done,
                             pending.size(), failed.load(), counts.skipped, eta)
              << std::flush;
  };
  run_parallel(pending.size(), options.jobs, options.threads_per_job, [&](std::size_t k) {
    const SweepCase& sc = cases[pending[k]];
    const bool ok = run_one(case_path, base, sc, options.out_dir / sc.folder);
    std::lock_guard<std::mutex> lock(report);
    ++finished;
    if (!ok) ++failed;
    if (options.rank == 0) write_sweep_csv(options.out_dir, vary, cases);
    progress();
  });
  if (options.progress && !pending.empty()) std::cerr << "\n";
  if (options.pull_off) {
    std::vector<fs::path> to_pull;
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (static_cast<int>(i % options.ranks) == options.rank && case_finished(folders[i]) &&
          !pulled_off(folders[i]))
        to_pull.push_back(folders[i]);
    run_parallel(to_pull.size(), options.jobs, options.threads_per_job, [&](std::size_t k) {
      pull_off_case(to_pull[k], *options.pull_off);
      std::lock_guard<std::mutex> lock(report);
      if (options.rank == 0) write_sweep_csv(options.out_dir, vary, cases);
    });
  }
  if (options.rank == 0) write_sweep_csv(options.out_dir, vary, cases);
  counts.ran = finished.load();
  counts.failed = failed.load();
  return counts;
}

}  // namespace coldspray::studies
