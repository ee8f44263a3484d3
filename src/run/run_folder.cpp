#include "run/run_folder.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "run/run_id.hpp"

namespace coldspray::run {

namespace fs = std::filesystem;

namespace {

// What the recorder writes beside the snapshots folder; the last is written last.
constexpr std::array<std::string_view, 7> kRunFiles = {
    "case.resolved.yaml", kRunIdFile,      "history.csv", "contact.csv",
    "probes.csv",         "snapshots.pvd", "summary.json"};

// The files it numbers by step: snapshots (Recorder::snapshot) and checkpoints
// (run/checkpoints.hpp).
constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kStepFiles = {
    {{"snapshots", ".vtu"}, {"checkpoints", ".h5"}}};

}  // namespace

std::vector<fs::path> step_files(const fs::path& dir, std::string_view extension) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (p.extension() == extension && p.filename().string().starts_with("step_"))
      found.push_back(p);
  }
  std::sort(found.begin(), found.end());  // step_NNNNNNNN: by step
  return found;
}

std::optional<fs::path> previous_run_result(const fs::path& folder) {
  std::error_code ec;
  for (std::string_view name : kRunFiles)
    if (fs::exists(folder / name, ec)) return folder / name;
  for (const auto& [dir, extension] : kStepFiles)
    if (const std::vector<fs::path> files = step_files(folder / dir, extension); !files.empty())
      return files.front();
  return std::nullopt;
}

void prepare_run_folder(const fs::path& folder) {
  io::make_output_folder(folder);
  io::make_output_folder(folder / "snapshots");
  for (std::string_view name : kRunFiles) fs::remove(folder / name);
  for (const auto& [dir, extension] : kStepFiles)
    for (const fs::path& p : step_files(folder / dir, extension)) fs::remove(p);
  remove_interrupted_writes(folder);
}

void remove_interrupted_writes(const fs::path& folder) {
  for (const char* dir : {"", "snapshots", "checkpoints"})
    io::remove_stale_temporaries(folder / dir);
}

}  // namespace coldspray::run
