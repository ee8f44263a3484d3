// Checkpoint and restart (docs/reliability.md): a run continued from a checkpoint writes the same
// bits as the uninterrupted run (every table, snapshot and summary field but the timing), for the
// MPM in r-z and in 3D with bonding and points leaving the grid, and for peridynamics with the
// control along the flow and contact; SIGINT stops a run with a checkpoint and exit 130, and
// after kill -9 the run continues from its last checkpoint.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;
const std::string kVerificationExamples =
    std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/";

// summary.json without what depends on the wall clock and the threads the run had.
nlohmann::json untimed_summary(const fs::path& run) {
  nlohmann::json j = nlohmann::json::parse(read_text(run / "summary.json"));
  for (const char* timing : {"wall_seconds", "particle_steps_per_second", "threads"})
    j.erase(timing);
  return j;
}

// The run's result files, relative to its folder: everything but its checkpoints and its id
// (run_id.txt, drawn at random for each run).
std::vector<fs::path> result_files(const fs::path& run) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(run))
    if (e.is_regular_file() && e.path().parent_path().filename() != "checkpoints" &&
        e.path().filename() != "run_id.txt")
      files.push_back(fs::relative(e.path(), run));
  std::sort(files.begin(), files.end());
  return files;
}

// Every result file of `restarted` equal to `whole`'s, byte for byte (summary.json, timing
// aside).
void expect_same_results(const fs::path& whole, const fs::path& restarted) {
  const std::vector<fs::path> files = result_files(whole);
  EXPECT_EQ(files, result_files(restarted));
  for (const fs::path& f : files) {
    if (f == "summary.json")
      EXPECT_EQ(untimed_summary(whole), untimed_summary(restarted));
    else
      EXPECT_TRUE(read_text(whole / f) == read_text(restarted / f)) << f;
  }
  EXPECT_EQ(untimed_summary(restarted)["status"], "ok");
}

// The finished checkpoint files (not one being written, step_N.h5.tmpPID).
std::vector<fs::path> checkpoints(const fs::path& run) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(run / "checkpoints"))
    if (e.path().extension() == ".h5") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Runs `case_file` with `sets` to its end in `whole`; copies the finished folder and restarts
// the copy from its checkpoint number `from` (the first by default; so that its tables and
// snapshots hold rows and files past the checkpoint, which the restart must cut and write
// again); compares the two.
void expect_restart_bit_identical(const std::string& case_file, const std::string& sets,
                                  const std::string& restart_flags = "", std::size_t from = 0) {
  const fs::path dir = make_temp_dir();
  const fs::path whole = dir / "whole", copy = dir / "copy";
  const auto r = run_coldspray("run '" + case_file + "' --quiet --out '" + whole.string() +
                               "' --set output.checkpoint_keep=10 " + sets);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<fs::path> written = checkpoints(whole);
  ASSERT_GE(written.size(), from + 3) << "mid-run checkpoints and the last one";
  fs::copy(whole, copy, fs::copy_options::recursive);
  const fs::path first = copy / "checkpoints" / written[from].filename();
  const auto restarted =
      run_coldspray("run --quiet --restart '" + first.string() + "' " + restart_flags);
  ASSERT_EQ(restarted.status, 0) << restarted.output;
  expect_same_results(whole, copy);
}

TEST(Restart, MpmAxisymmetricWithBondingIsBitIdentical) {
  expect_restart_bit_identical(
      kVerificationExamples + "bonding-impact.yaml",
      "--set bodies.particle.spacing=0.5um --set bodies.substrate.spacing=0.5um "
      "--set grid.cell_size=1um --set solver.end_time=6ns --set output.checkpoint_interval=2ns "
      "--set output.snapshot_interval=1ns");
}

TEST(Restart, Mpm3dQuarterWithBondsFormedIsBitIdentical) {
  // The 14 um Al impact at 810 m/s on a quarter model at 1 um spacing: the particle's bonded
  // area more than doubles after the checkpoint at 3 ns (abp 0.31 then, 0.70 at 8 ns).
  expect_restart_bit_identical(
      kVerificationExamples + "sliding-impact-3d.yaml",
      "--set bonding.model=energy --set bodies.particle.spacing=1um "
      "--set bodies.substrate.spacing=1um --set grid.cell_size=2um --set solver.end_time=8ns "
      "--set metrics.verdict_extensions=0 --set output.checkpoint_interval=3ns "
      "--set output.snapshot_interval=2ns");
}

TEST(Restart, Mpm3dWithBondingAndDeparturesIsBitIdentical) {
  // The fragment leaves the grid after the first checkpoint: the restart reads fewer points
  // than its setup seeds.
  expect_restart_bit_identical(kVerificationExamples + "fragment-leaves.yaml",
                               "--set bonding.model=energy --set output.checkpoint_interval=0.4ns "
                               "--set output.snapshot_interval=0.3ns");
}

TEST(Restart, PeridynamicsWithFlowControlAndContactIsBitIdentical) {
  expect_restart_bit_identical(
      kVerificationExamples + "pd-quarter-impact.yaml",
      "--set symmetry.x=0um --set symmetry.y=0um --set peridynamics.control_stiffness=flow "
      "--set solver.end_time=6ns --set output.checkpoint_interval=2ns "
      "--set output.snapshot_interval=1ns",
      "--threads 2");  // the tests run on one thread: the bits do not depend on the threads
}

TEST(Restart, PeridynamicsWithInterfaceBondsIsBitIdentical) {
  // Contact model 2's bonds remember their largest stretch: the checkpoint carries it. The
  // particle, still undecided at 6 ns, would extend the run to 46 ns (metrics.verdict_extensions):
  // not what this test checks, and 8 times the steps under the sanitizers.
  expect_restart_bit_identical(
      kVerificationExamples + "pd-quarter-impact.yaml",
      "--set symmetry.x=0um --set symmetry.y=0um --set contact.peridynamics.model=interface-bonds "
      "--set solver.end_time=6ns --set metrics.verdict_extensions=0 "
      "--set output.checkpoint_interval=2ns --set output.snapshot_interval=1ns");
}

TEST(Restart, PeridynamicsWithSubcyclingIsBitIdentical) {
  // The small sphere takes two steps per step of the large one; restarted from 9 ns, within
  // the collision (about 7-11.5 ns), where the large one's first kick reads its last contact
  // force.
  expect_restart_bit_identical(std::string(COLDSPRAY_TEST_DATA) + "/cli/pd-two-spacings.yaml",
                               "--set peridynamics.subcycling=true "
                               "--set output.checkpoint_interval=3ns "
                               "--set output.snapshot_interval=2ns",
                               "", /*from=*/2);
}

TEST(Restart, RefusesOverridesAndMissingCheckpoints) {
  const fs::path dir = make_temp_dir();
  const auto empty = run_coldspray("run --restart '" + dir.string() + "'");
  EXPECT_EQ(empty.status, 2) << empty.output;
  EXPECT_NE(empty.output.find("holds no checkpoint"), std::string::npos) << empty.output;
  const auto sets = run_coldspray("run --restart '" + dir.string() + "' --set solver.cfl=0.1");
  EXPECT_EQ(sets.status, 2) << sets.output;
  const fs::path loose = dir / "step_00000001.h5";
  std::ofstream(loose) << "text";
  const auto outside = run_coldspray("run --restart '" + loose.string() + "'");
  EXPECT_EQ(outside.status, 2) << outside.output;
  EXPECT_NE(outside.output.find("is not in a run folder's checkpoints/"), std::string::npos)
      << outside.output;
  fs::create_directories(dir / "checkpoints");
  const fs::path not_hdf5 = dir / "checkpoints" / "step_00000001.h5";
  std::ofstream(not_hdf5) << "text";
  const auto garbage = run_coldspray("run --restart '" + not_hdf5.string() + "'");
  EXPECT_EQ(garbage.status, 2) << garbage.output;
  EXPECT_NE(garbage.output.find("has no checksum header"), std::string::npos) << garbage.output;
}

// The last line of a table.
std::string last_row(const fs::path& table) {
  std::istringstream in(read_text(table));
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

// The row's fields after its first (the time).
std::string after_time(const std::string& row) { return row.substr(row.find(',')); }

TEST(Restart, AnotherCaseStartsFromACheckpointsState) {
  // A run of 2 ns more from the impact's last checkpoint: its first history row (t = 0) holds
  // the impact's last state, every energy and body column to the digit.
  const fs::path dir = make_temp_dir();
  const std::string coarse =
      " --set bodies.particle.spacing=0.5um --set bodies.substrate.spacing=0.5um "
      "--set grid.cell_size=1um";
  const auto impact =
      run_coldspray("run '" + kVerificationExamples + "bonding-impact.yaml' --quiet --out '" +
                    (dir / "impact").string() + "' --set solver.end_time=6ns" + coarse);
  ASSERT_EQ(impact.status, 0) << impact.output;
  const fs::path last = checkpoints(dir / "impact").back();
  const auto after =
      run_coldspray("run '" + kVerificationExamples + "bonding-impact.yaml' --quiet --out '" +
                    (dir / "after").string() + "' --initial-state '" + last.string() +
                    "' --set solver.end_time=2ns" + coarse);
  ASSERT_EQ(after.status, 0) << after.output;
  std::istringstream history(read_text(dir / "after" / "history.csv"));
  std::string header, first;
  std::getline(history, header);
  std::getline(history, first);
  EXPECT_EQ(first.substr(0, first.find(',')), "0");
  EXPECT_EQ(after_time(first), after_time(last_row(dir / "impact" / "history.csv")));

  // Other bodies than the checkpoint's: refused, naming the checkpoint.
  const auto finer =
      run_coldspray("run '" + kVerificationExamples + "bonding-impact.yaml' --quiet --out '" +
                    (dir / "finer").string() + "' --initial-state '" + last.string() +
                    "' --set grid.cell_size=1um");
  EXPECT_EQ(finer.status, 2) << finer.output;
  EXPECT_NE(finer.output.find("holds other bodies than this case seeds"), std::string::npos)
      << finer.output;
  EXPECT_FALSE(fs::exists(dir / "finer"));
}

// Waits until `run` holds a checkpoint (or `pid` ended); returns whether one appeared.
bool wait_for_checkpoint(const fs::path& run, pid_t pid) {
  for (int k = 0; k < 6000; ++k) {
    if (fs::exists(run / "checkpoints") && !checkpoints(run).empty()) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// The peridynamics quarter impact with a checkpoint every 0.5 ns of simulated time, to 6 ns
// (long_run_args): a signal sent once the first checkpoint exists lands mid-run (the rest takes
// 0.3 s on one thread in the release build, 15 s under the sanitizers; the test looks every
// 10 ms).
const std::vector<std::string> kLongRunSets = {"--set", "symmetry.x=0um",
                                               "--set", "symmetry.y=0um",
                                               "--set", "output.checkpoint_interval=0.5ns",
                                               "--set", "output.snapshot_interval=5ns"};
const std::string kLongRunEnd = "solver.end_time=6ns";

std::vector<std::string> long_run_args(const fs::path& out) {
  std::vector<std::string> args = {"run",        kVerificationExamples + "pd-quarter-impact.yaml",
                                   "--quiet",    "--out",
                                   out.string(), "--set",
                                   kLongRunEnd};
  args.insert(args.end(), kLongRunSets.begin(), kLongRunSets.end());
  return args;
}

// Runs the long case to its end in `whole`.
void run_whole_long_case(const fs::path& whole) {
  std::string args = "run '" + kVerificationExamples + "pd-quarter-impact.yaml' --quiet --out '" +
                     whole.string() + "' --set " + kLongRunEnd;
  for (std::size_t k = 0; k < kLongRunSets.size(); k += 2) args += " --set " + kLongRunSets[k + 1];
  const auto r = run_coldspray(args);
  ASSERT_EQ(r.status, 0) << r.output;
}

// Runs the long case whole, and again stopped by `signal` once its first checkpoint exists;
// returns the stopped run's folder, after checking its exit status.
struct StoppedRun {
  fs::path whole, stopped;
};
StoppedRun stop_long_run(int signal, int expected_status) {
  const fs::path dir = make_temp_dir();
  const StoppedRun run{dir / "whole", dir / "stopped"};
  run_whole_long_case(run.whole);
  const pid_t pid = spawn_coldspray(long_run_args(run.stopped));
  EXPECT_TRUE(wait_for_checkpoint(run.stopped, pid));
  kill(pid, signal);
  EXPECT_EQ(exit_status(pid), expected_status);
  return run;
}

void expect_restart_finishes(const StoppedRun& run) {
  const auto r = run_coldspray("run --quiet --restart '" + run.stopped.string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  expect_same_results(run.whole, run.stopped);
}

TEST(Restart, SigintStopsWithACheckpointAndTheRestartFinishesTheRun) {
  const StoppedRun run = stop_long_run(SIGINT, 130);
  EXPECT_EQ(untimed_summary(run.stopped)["status"], "interrupted");
  expect_restart_finishes(run);
}

TEST(Restart, SigtermStopsTheSameWayWithStatus143) {
  const StoppedRun run = stop_long_run(SIGTERM, 143);
  EXPECT_EQ(untimed_summary(run.stopped)["status"], "interrupted");
  expect_restart_finishes(run);
}

TEST(Restart, AfterKill9TheRunContinuesFromItsLastCheckpoint) {
  const StoppedRun run = stop_long_run(SIGKILL, -SIGKILL);
  EXPECT_FALSE(fs::exists(run.stopped / "summary.json"));
  expect_restart_finishes(run);
}

TEST(Restart, SigintStopsASweepWhichTheSameCommandFinishes) {
  const fs::path dir = make_temp_dir();
  const fs::path sweep = dir / "sweep";
  std::vector<std::string> args = {"sweep",  kVerificationExamples + "pd-quarter-impact.yaml",
                                   "--vary", "solver.end_time=5ns,5.5ns,6ns",
                                   "--jobs", "1",
                                   "--out",  sweep.string()};
  args.insert(args.end(), kLongRunSets.begin(), kLongRunSets.end());
  const pid_t pid = spawn_coldspray(args);
  fs::path first;
  for (int k = 0; k < 6000 && first.empty(); ++k) {
    if (fs::exists(sweep))
      for (const auto& e : fs::directory_iterator(sweep))
        if (e.is_directory() && fs::exists(e.path() / "checkpoints") &&
            !checkpoints(e.path()).empty())
          first = e.path();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_FALSE(first.empty()) << "no case wrote a checkpoint";
  kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130);
  EXPECT_EQ(untimed_summary(first)["status"], "interrupted");
  std::string again = "sweep '" + kVerificationExamples +
                      "pd-quarter-impact.yaml' --vary solver.end_time=5ns,5.5ns,6ns --jobs 1 "
                      "--out '" +
                      sweep.string() + "'";
  for (std::size_t k = 0; k < kLongRunSets.size(); k += 2) again += " --set " + kLongRunSets[k + 1];
  const auto r = run_coldspray(again);
  ASSERT_EQ(r.status, 0) << r.output;
  int cases = 0;
  for (const auto& e : fs::directory_iterator(sweep))
    if (e.is_directory()) {
      EXPECT_EQ(untimed_summary(e.path())["status"], "ok") << e.path();
      ++cases;
    }
  EXPECT_EQ(cases, 3);
}

// The PD paper's impact at D/25 (30 um at 1.2 um) takes seconds to build its families and shape
// tensors (3.5 s on one thread in the release build): a SIGTERM 300 ms in lands in its set-up,
// which stops where it stands, before the run's folder exists. (It used to finish the set-up,
// run a step and write a checkpoint and summary.json: issue 53.)
TEST(Restart, SigtermDuringTheSetUpStopsItBeforeAnythingIsWritten) {
  const fs::path dir = make_temp_dir();
  const fs::path out = dir / "impact";
  const pid_t pid =
      spawn_coldspray({"impact", "--solver", "peridynamics", "--diameter", "30um", "--velocity",
                       "500m/s", "--spacing", "1.2um", "--quiet", "--out", out.string()},
                      dir / "log.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGTERM);
  EXPECT_EQ(exit_status(pid), 143);
  const std::string log = read_text(dir / "log.txt");
  EXPECT_NE(log.find("interrupted during set-up ("), std::string::npos) << log;
  EXPECT_NE(log.find("); nothing was written"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(out));
}

// A second signal ends the program at once, in work that does not read the stop flag: here the
// YAML parse of a case of 1 000 000 keys (10 s in the release build), with both signals 300 ms
// apart inside it.
TEST(Restart, ASecondSigintEndsTheProgramAtOnce) {
  const fs::path dir = make_temp_dir();
  {
    std::ofstream big(dir / "big.yaml");
    big << "name: big\n";
    for (int k = 0; k < 1000000; ++k) big << "key" << k << ": " << k << "\n";
  }
  const pid_t pid = spawn_coldspray({"check", (dir / "big.yaml").string()}, dir / "log.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), -SIGINT);
}

TEST(Restart, SigintStopsACalibrationWhichTheSameCommandFinishes) {
  // The tiny calibration of the studies' tests, run to 60 ns so that the signal lands while its
  // bond families run.
  const fs::path dir = make_temp_dir();
  std::string text = read_text(std::string(COLDSPRAY_TEST_DATA) + "/cli/calibrate-tiny.yaml");
  text.replace(text.find("end_time: 3 ns"), 14, "end_time: 60 ns");
  std::ofstream(dir / "calib.yaml") << text;
  const std::vector<std::string> args = {"calibrate", (dir / "calib.yaml").string(),
                                         "--out",     (dir / "cal").string(),
                                         "--quiet",   "--jobs",
                                         "2",         "--threads-per-job",
                                         "1"};
  const pid_t pid = spawn_coldspray(args);
  bool running = false;
  for (int k = 0; k < 6000 && !running; ++k) {
    if (fs::exists(dir / "cal"))
      for (const auto& e : fs::recursive_directory_iterator(dir / "cal"))
        running = running || e.path().filename() == "history.csv";
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(running);
  kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130);
  int interrupted = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "cal"))
    if (e.path().filename() == "summary.json")
      interrupted += untimed_summary(e.path().parent_path())["status"] == "interrupted";
  EXPECT_GT(interrupted, 0);
  std::string again;
  for (std::size_t k = 0; k < args.size(); ++k) again += " '" + args[k] + "'";
  const auto r = run_coldspray(again);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("(0 failed)"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(dir / "cal" / "runs.csv").find("interrupted"), std::string::npos);
}

}  // namespace
}  // namespace coldspray::testing
