#include "studies/case_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "core/error.hpp"
#include "run/interrupt.hpp"
#include "run/run.hpp"
#include "run/summary.hpp"
#include "studies/task_pool.hpp"

namespace coldspray::studies {

namespace fs = std::filesystem;

bool case_finished(const fs::path& folder) {
  if (!fs::exists(folder / "summary.json")) return false;
  const nlohmann::json summary = read_summary(folder);
  return !(summary.is_object() && summary.value("status", "") == "interrupted");
}

nlohmann::json read_summary(const fs::path& folder) {
  std::ifstream in(folder / "summary.json");
  if (!in) return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

namespace {

// A case that failed before run_case could record it gets a summary with the failure as status.
void record_failure(const fs::path& folder, const std::string& status) {
  run::Summary s;
  s.status = status;
  run::write_summary_json(s, folder / "summary.json");
}

}  // namespace

bool run_in_folder(const fs::path& folder, const std::function<case_file::Case()>& load) {
  if (run::pending_interrupt()) return false;  // the study stops (run_parallel)
  fs::remove_all(folder);
  fs::create_directories(folder);
  try {
    const case_file::Case c = load();
    run::RunOptions options;
    options.out_dir = folder;
    options.progress = false;
    run::run_case(c, options);
  } catch (...) {
    return record_outcome(folder, std::current_exception());
  }
  return true;
}

bool record_outcome(const fs::path& folder, const std::exception_ptr& failure) {
  if (!failure) return true;
  try {
    std::rethrow_exception(failure);
  } catch (const run::Interrupted&) {
    // Its summary, if it wrote one, says "interrupted": not finished, run again next time.
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

std::vector<std::size_t> pending_folders(const std::vector<fs::path>& folders, int rank, int ranks,
                                         std::size_t& skipped) {
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(ranks)) != rank) continue;
    if (case_finished(folders[i]))
      ++skipped;
    else
      pending.push_back(i);
  }
  return pending;
}

std::string csv_number(double x) { return std::isnan(x) ? "nan" : fmt::format("{:.10g}", x); }

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

void run_parallel(std::size_t count, int jobs, int threads_per_job,
                  const std::function<void(std::size_t)>& body) {
  TaskPool pool(std::max(1, std::min<int>(jobs, static_cast<int>(count))), threads_per_job);
  for (std::size_t k = 0; k < count; ++k) pool.submit([&body, k] { body(k); });
  pool.run();
  throw_if_interrupted();
}

void throw_if_interrupted() {
  if (const int signal = run::pending_interrupt())
    throw run::Interrupted(signal,
                           "interrupted: the finished cases are kept; the same command again "
                           "runs the others");
}

}  // namespace coldspray::studies
