#include "run/run_folder.hpp"

#include <array>
#include <string_view>
#include <vector>

#include "io/output_folder.hpp"

namespace coldspray::run {

namespace fs = std::filesystem;

namespace {

// What the recorder writes beside the snapshots folder; the last is written last.
constexpr std::array<std::string_view, 6> kRunFiles = {"case.resolved.yaml", "history.csv",
                                                       "contact.csv",        "probes.csv",
                                                       "snapshots.pvd",      "summary.json"};

// The snapshots in `folder`/snapshots: snapshots/step_NNNNNNNN.vtu (Recorder::snapshot).
std::vector<fs::path> snapshots_in(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (fs::directory_iterator it(folder / "snapshots", ec), end; !ec && it != end;
       it.increment(ec)) {
    const fs::path& p = it->path();
    if (p.extension() == ".vtu" && p.filename().string().starts_with("step_")) found.push_back(p);
  }
  return found;
}

}  // namespace

std::optional<fs::path> previous_run_result(const fs::path& folder) {
  std::error_code ec;
  for (std::string_view name : kRunFiles)
    if (fs::exists(folder / name, ec)) return folder / name;
  const std::vector<fs::path> snapshots = snapshots_in(folder);
  if (!snapshots.empty()) return snapshots.front();
  return std::nullopt;
}

void prepare_run_folder(const fs::path& folder) {
  io::make_output_folder(folder);
  io::make_output_folder(folder / "snapshots");
  for (std::string_view name : kRunFiles) fs::remove(folder / name);
  for (const fs::path& p : snapshots_in(folder)) fs::remove(p);
}

}  // namespace coldspray::run
