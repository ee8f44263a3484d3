// Nothing lost, nothing silently wrong (docs/reliability.md): a restart refuses, with exit status
// 2 and before it changes the folder, a checkpoint that is damaged, cut short, another run's, or
// not a regular file, and a folder whose tables are missing or changed; a failed write (a full
// disk) is a fault with exit status 3 that leaves no partial checkpoint and no "ok"; one process
// at a time holds a run folder; an unwritable output named on the command line is bad input.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

// The 14 um aluminium impact to 3 ns with a checkpoint every 0.5 ns (2.5 MB each) and no
// snapshots but the first and last (1.2 MB each): a fifth of a second in the release build.
std::string short_run(const fs::path& out, const std::string& extra = "") {
  return "run '" + std::string(COLDSPRAY_SOURCE_DIR) +
         "/examples/al-14um-810.yaml' --quiet --set solver.end_time=3ns "
         "--set output.checkpoint_interval=0.5ns --set output.snapshot_interval=0 "
         "--set output.checkpoint_keep=10 --out '" +
         out.string() + "' " + extra;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every file of a folder, by path, with its bytes: what a refused restart must leave as it was.
std::vector<std::pair<fs::path, std::string>> snapshot_of(const fs::path& run) {
  std::vector<std::pair<fs::path, std::string>> all;
  for (const auto& e : fs::recursive_directory_iterator(run))
    if (e.is_regular_file()) all.emplace_back(e.path(), read_text(e.path()));
  std::sort(all.begin(), all.end());
  return all;
}

fs::path finished_run(const fs::path& out, const std::string& extra = "") {
  const auto r = run_coldspray(short_run(out, extra));
  EXPECT_EQ(r.status, 0) << r.output;
  return out;
}

fs::path latest_checkpoint(const fs::path& run) { return files_in(run / "checkpoints").back(); }

void flip_byte(const fs::path& file, std::uintmax_t at) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(static_cast<std::streamoff>(at));
  const char old = static_cast<char>(f.get());
  f.seekp(static_cast<std::streamoff>(at));
  f.put(static_cast<char>(old ^ 0x01));
}

// `restart` of `run` is refused with status 2 and `message`, and the folder is as it was.
void expect_refused(const fs::path& run, const std::string& message,
                    const std::string& restart = "") {
  const auto before = snapshot_of(run);
  const auto r =
      run_coldspray("run --quiet --restart '" + (restart.empty() ? run.string() : restart) + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, message)) << r.output;
  EXPECT_TRUE(snapshot_of(run) == before) << "a refused restart changed the folder";
}

TEST(RunFolderIntegrity, AFlippedBitAnywhereInTheLatestCheckpointIsRefused) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  const fs::path latest = latest_checkpoint(run);
  const std::string original = read_text(latest);
  // In the seal's header, HDF5's superblock, and through the data, 17 places in all.
  std::vector<std::uintmax_t> places = {0, 20, 40, 300, 511, 512, 600};
  for (int k = 1; k <= 10; ++k) places.push_back(original.size() * k / 11);
  for (const std::uintmax_t at : places) {
    flip_byte(latest, at);
    expect_refused(run, "step_");
    std::ofstream(latest, std::ios::binary) << original;
  }
}

TEST(RunFolderIntegrity, ACheckpointCutShortIsRefused) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  const fs::path latest = latest_checkpoint(run);
  fs::resize_file(latest, fs::file_size(latest) - 1000);
  expect_refused(run, "is damaged");
}

TEST(RunFolderIntegrity, AnotherRunsCheckpointIsRefusedEvenOfTheSameCase) {
  const fs::path dir = make_temp_dir();
  const fs::path run = finished_run(dir / "run");
  const fs::path faster =
      finished_run(dir / "faster", "--set 'bodies.particle.velocity=[0, 0, -811 m/s]'");
  const fs::path twin = finished_run(dir / "twin");
  fs::copy_file(latest_checkpoint(faster), run / "checkpoints" / "step_00009000.h5");
  expect_refused(run, "key 'run_id': is run ");
  fs::remove(run / "checkpoints" / "step_00009000.h5");
  fs::copy_file(latest_checkpoint(twin), run / "checkpoints" / "step_00009000.h5");
  expect_refused(run, "a folder continues only from its own checkpoints");
}

TEST(RunFolderIntegrity, AChangedCaseFileIsRefused) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  std::ofstream(run / "case.resolved.yaml", std::ios::app) << "# edited\n";
  expect_refused(run, "key 'case': differs from");
}

TEST(RunFolderIntegrity, AMissingOrChangedTableIsRefused) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  const std::string history = read_text(run / "history.csv");
  fs::remove(run / "history.csv");
  expect_refused(run, "history.csv: is missing");
  // Cut mid-row, before the length the first checkpoint recorded.
  std::ofstream(run / "history.csv", std::ios::binary) << history.substr(0, 300);
  expect_refused(run, "has 300 bytes where its checkpoint recorded",
                 files_in(run / "checkpoints").front().string());
  // As long, but not ending a row there.
  std::string shifted = history;
  shifted.insert(shifted.begin() + 100, 'x');
  std::ofstream(run / "history.csv", std::ios::binary) << shifted;
  expect_refused(run, "does not end a row at byte");
  fs::remove(run / "run_id.txt");
  expect_refused(run, "run_id.txt: is missing");
}

TEST(RunFolderIntegrity, AFifoInPlaceOfACheckpointIsRefusedWithoutBlocking) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  ASSERT_EQ(::mkfifo((run / "checkpoints" / "step_00009000.h5").c_str(), 0644), 0);
  // `timeout` ends a restart that blocks in open() (status 124), as it did before.
  const auto r = run_coldspray_under("timeout 60", "run --quiet --restart '" + run.string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "step_00009000.h5: is not a regular file")) << r.output;
}

TEST(RunFolderIntegrity, StaleTemporaryFilesGoAtRestartAndWithOverwrite) {
  const fs::path run = finished_run(fs::path(make_temp_dir()) / "run");
  const fs::path kept = run / "notes.tmp";  // not a temporary of ours: no pid after .tmp
  for (const fs::path& stale :
       {run / "checkpoints" / "step_00000200.h5.tmp4242",
        run / "snapshots" / "step_00000200.vtu.tmp4242", run / "summary.json.tmp77", kept})
    std::ofstream(stale) << "half";
  const auto restarted = run_coldspray("run --quiet --restart '" + run.string() + "'");
  EXPECT_EQ(restarted.status, 0) << restarted.output;
  EXPECT_FALSE(fs::exists(run / "checkpoints" / "step_00000200.h5.tmp4242"));
  EXPECT_FALSE(fs::exists(run / "snapshots" / "step_00000200.vtu.tmp4242"));
  EXPECT_FALSE(fs::exists(run / "summary.json.tmp77"));
  EXPECT_TRUE(fs::exists(kept));
  std::ofstream(run / "checkpoints" / "step_00000300.h5.tmp4243") << "half";
  const auto again = run_coldspray(short_run(run, "--overwrite"));
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_FALSE(fs::exists(run / "checkpoints" / "step_00000300.h5.tmp4243"));
}

// A write that fails partway: every file the run writes may grow to 2 MB only (prlimit; with
// SIGXFSZ ignored, a write past it fails with EFBIG, as on a full disk). The first checkpoint
// (2.5 MB) cannot be written; the run stops at it.
TEST(RunFolderIntegrity, AFailedWriteIsAFaultThatLeavesNoPartialCheckpoint) {
  const fs::path run = fs::path(make_temp_dir()) / "run";
  const auto r = run_coldspray_under("trap '' XFSZ; prlimit --fsize=2000000", short_run(run));
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_TRUE(has(r, "fault: writing '")) << r.output;
  EXPECT_TRUE(has(r, "File too large")) << r.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(run / "summary.json"));
  EXPECT_EQ(summary["status"].get<std::string>().rfind("fault: writing '", 0), 0u) << summary;
  EXPECT_TRUE(files_in(run / "checkpoints").empty()) << "no checkpoint, whole or partial";
  const auto restart = run_coldspray("run --quiet --restart '" + run.string() + "'");
  EXPECT_EQ(restart.status, 2) << restart.output;
  EXPECT_TRUE(has(restart, "holds no checkpoint")) << restart.output;
}

TEST(RunFolderIntegrity, ASecondProcessIsRefusedTheFolderNamingTheFirst) {
  const fs::path dir = make_temp_dir();
  const fs::path out = dir / "run";
  // The default case to 1 us: its set-up takes a fraction of a second, its run minutes; it holds
  // the folder from the end of its set-up.
  const pid_t first =
      spawn_coldspray({"run", std::string(COLDSPRAY_SOURCE_DIR) + "/examples/al-14um-810.yaml",
                       "--quiet", "--set", "solver.end_time=1us", "--out", out.string()});
  bool held = false;
  for (int k = 0; k < 12000 && !held; ++k) {
    held = fs::exists(out / ".coldspray.lock") && !read_text(out / ".coldspray.lock").empty();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!held) {
    kill(first, SIGKILL);
    exit_status(first);
    FAIL() << "the first run never took the folder's lock";
  }
  const auto second = run_coldspray(short_run(out, "--overwrite"));
  const auto sweep = run_coldspray("sweep '" + std::string(COLDSPRAY_SOURCE_DIR) +
                                   "/examples/al-14um-810.yaml' --vary solver.cfl=0.3 --out '" +
                                   out.string() + "'");
  kill(first, SIGKILL);
  exit_status(first);
  EXPECT_EQ(second.status, 2) << second.output;
  EXPECT_TRUE(
      has(second, "is in use by another coldspray process (pid " + std::to_string(first) + ")"))
      << second.output;
  EXPECT_EQ(sweep.status, 2) << sweep.output;
  EXPECT_TRUE(has(sweep, "is in use by another coldspray process")) << sweep.output;
  // kill -9 released it: the folder is free again.
  const auto third = run_coldspray(short_run(out, "--overwrite"));
  EXPECT_EQ(third.status, 0) << third.output;
}

TEST(RunFolderIntegrity, AnUnwritableOutputFileIsBadInputBeforeTheWork) {
  // /proc takes no new files, even from root.
  const auto test = run_coldspray(
      "material-test --material al-ptw --strain-rate '1e7 1/s' --final-strain -0.5 --out "
      "/proc/coldspray-curve.csv");
  EXPECT_EQ(test.status, 2) << test.output;
  EXPECT_TRUE(has(test, "--out: cannot write '/proc/coldspray-curve.csv'")) << test.output;
  const auto write_case = run_coldspray(
      "impact --material al-ptw --diameter 14um --velocity 800m/s --write-case /proc/case.yaml");
  EXPECT_EQ(write_case.status, 2) << write_case.output;
  EXPECT_TRUE(has(write_case, "--write-case: cannot write '/proc/case.yaml'")) << write_case.output;
}

}  // namespace
}  // namespace coldspray::testing
