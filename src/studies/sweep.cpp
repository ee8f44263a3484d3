#include "studies/sweep.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "run/run.hpp"
#include "run/summary.hpp"

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

bool case_finished(const fs::path& folder) { return fs::exists(folder / "summary.json"); }

namespace {

// A case that failed before run_case could record it gets a summary with the failure as status.
void record_failure(const fs::path& folder, const std::string& status) {
  run::Summary s;
  s.status = status;
  run::write_summary_json(s, folder / "summary.json");
}

// Runs one case into its (cleared) folder; false if it failed.
bool run_one(const std::string& case_path, const std::vector<case_file::Override>& base,
             const SweepCase& sc, const fs::path& folder) {
  fs::remove_all(folder);
  fs::create_directories(folder);
  {
    std::ofstream list(folder / "overrides.txt");
    for (const auto& o : sc.overrides) list << o.key << "=" << o.value << "\n";
  }
  std::vector<case_file::Override> overrides = base;
  overrides.insert(overrides.end(), sc.overrides.begin(), sc.overrides.end());
  try {
    const case_file::Case c = case_file::load_case(case_path, overrides);
    run::RunOptions options;
    options.out_dir = folder;
    options.progress = false;
    run::run_case(c, options);
    return true;
  } catch (const InputError& e) {
    record_failure(folder, std::string("input error: ") + e.what());
  } catch (const RunFault& e) {
    // run_case has written the summary with the fault; keep a record if it could not.
    if (!case_finished(folder)) record_failure(folder, std::string("fault: ") + e.what());
  } catch (const std::exception& e) {
    record_failure(folder, std::string("error: ") + e.what());
  }
  return false;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string number(const nlohmann::json& j) {
  return j.is_number()    ? fmt::format("{:.10g}", j.get<double>())
         : j.is_boolean() ? std::string(j.get<bool>() ? "1" : "0")
                          : std::string("nan");
}

constexpr const char* kBodyColumns[] = {"cor",
                                        "v_rest",
                                        "abp",
                                        "pbcp",
                                        "bonded",
                                        "mean_eqps",
                                        "max_temperature",
                                        "plastic_energy_density",
                                        "jetted_fraction",
                                        "crater_depth",
                                        "flattening_ratio"};

nlohmann::json read_summary(const fs::path& folder) {
  std::ifstream in(folder / "summary.json");
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

}  // namespace

void write_sweep_csv(const fs::path& out_dir, const std::vector<Variation>& vary,
                     const std::vector<SweepCase>& cases) {
  std::vector<nlohmann::json> summaries;
  std::vector<std::string> bodies;
  for (const SweepCase& sc : cases) {
    summaries.push_back(case_finished(out_dir / sc.folder) ? read_summary(out_dir / sc.folder)
                                                           : nlohmann::json());
    const auto& s = summaries.back();
    if (bodies.empty() && s.is_object() && s.contains("bodies") && !s["bodies"].empty())
      for (const auto& [name, _] : s["bodies"].items()) bodies.push_back(name);
  }
  io::write_atomically(out_dir / "sweep.csv", [&](std::ostream& out) {
    out << "case,status";
    for (const Variation& v : vary) out << "," << csv_field(v.key);
    out << ",steps,time,wall_seconds,energy_error,bonded";
    for (const auto& b : bodies)
      for (const char* q : kBodyColumns) out << "," << csv_field(b + "." + q);
    out << "\n";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const nlohmann::json& s = summaries[i];
      const bool done = s.is_object() && s.contains("status");
      out << cases[i].folder << ","
          << csv_field(done ? s["status"].get<std::string>() : std::string("pending"));
      for (const auto& o : cases[i].overrides) out << "," << csv_field(o.value);
      auto field = [&](const char* a, const char* b = nullptr) {
        if (!done || !s.contains(a)) return std::string("nan");
        return number(b ? s[a].value(b, nlohmann::json()) : s[a]);
      };
      out << "," << field("steps") << "," << field("time") << "," << field("wall_seconds") << ","
          << field("energy", "relative_error") << "," << field("system", "bonded");
      for (const auto& b : bodies)
        for (const char* q : kBodyColumns) {
          const bool has = done && s.contains("bodies") && s["bodies"].contains(b);
          out << "," << (has ? number(s["bodies"][b].value(q, nlohmann::json())) : "nan");
        }
      out << "\n";
    }
  });
}

SweepCounts run_sweep(const std::string& case_path, const std::vector<case_file::Override>& base,
                      const std::vector<Variation>& vary, const SweepOptions& options) {
  // Bad input stops the sweep before anything runs: the base case and every combination must
  // load (an error names --set or --vary).
  for (const auto& overrides : combinations(vary)) {
    std::vector<case_file::Override> all = base;
    all.insert(all.end(), overrides.begin(), overrides.end());
    case_file::load_case(case_path, all);
  }
  const std::vector<SweepCase> cases = sweep_cases(vary);
  fs::create_directories(options.out_dir);

  SweepCounts counts;
  counts.cases = cases.size();
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(options.ranks)) != options.rank) continue;
    if (case_finished(options.out_dir / cases[i].folder))
      ++counts.skipped;
    else
      pending.push_back(i);
  }

  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(pending.size())));
  const int threads = options.threads_per_job > 0 ? options.threads_per_job
                                                  : std::max(1, omp_get_max_threads() / jobs);
  std::atomic<std::size_t> next{0};
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
  auto worker = [&] {
    omp_set_num_threads(threads);
    for (std::size_t k = next++; k < pending.size(); k = next++) {
      const SweepCase& sc = cases[pending[k]];
      const bool ok = run_one(case_path, base, sc, options.out_dir / sc.folder);
      std::lock_guard<std::mutex> lock(report);
      ++finished;
      if (!ok) ++failed;
      if (options.rank == 0) write_sweep_csv(options.out_dir, vary, cases);
      progress();
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (options.progress && !pending.empty()) std::cerr << "\n";
  if (options.rank == 0) write_sweep_csv(options.out_dir, vary, cases);
  counts.ran = finished.load();
  counts.failed = failed.load();
  return counts;
}

}  // namespace coldspray::studies
