// `coldspray sweep`: one folder and one sweep.csv row per case, a failing case recorded without
// stopping the others, and a rerun that skips finished cases.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::cli {
namespace {

namespace fs = std::filesystem;
using testing::make_temp_dir;
using testing::read_text;
using testing::run_coldspray;

// The escape case: a block at 1 m/s stays on its small grid; at 1000 m/s it leaves it (a fault).
const std::string kSweep = "sweep '" + std::string(COLDSPRAY_TEST_DATA) +
                           "/cli/escape.yaml' --out sw --quiet --jobs 2 "
                           "--vary 'bodies.block.velocity=[0, 0, 1 m/s],[0, 0, 1000 m/s]'";

TEST(Cli, SweepRecordsAFailingCaseAndResumes) {
  const std::string dir = make_temp_dir();
  const auto first = run_coldspray(kSweep, dir);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("2 cases, 2 run now (1 failed), 0 finished before"),
            std::string::npos)
      << first.output;
  const fs::path sw = fs::path(dir) / "sw";
  const std::string table = read_text(sw / "sweep.csv");
  EXPECT_NE(table.find("case_0001,ok,\"[0, 0, 1 m/s]\""), std::string::npos) << table;
  // The system's verdict, and the body's measures and verdict (docs/studies.md): the block has no
  // bonded area, so it reads rebounded.
  EXPECT_NE(table.find(",energy_error,bonded,outcome,block.cor,"), std::string::npos) << table;
  EXPECT_NE(
      table.find(",block.flattening_ratio,block.outcome,block.separation_speed,block.margin\n"),
      std::string::npos)
      << table;
  EXPECT_NE(table.find(",0,rebounded,"), std::string::npos) << table;
  EXPECT_NE(table.find("case_0002,\"fault: body 'block'"), std::string::npos) << table;

  const auto again = run_coldspray(kSweep, dir);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("0 run now (0 failed), 2 finished before"), std::string::npos)
      << again.output;

  // A case killed in flight leaves a folder without summary.json: only it runs again.
  fs::remove(sw / "case_0001" / "summary.json");
  const auto resumed = run_coldspray(kSweep, dir);
  EXPECT_NE(resumed.output.find("1 run now (0 failed), 1 finished before"), std::string::npos)
      << resumed.output;
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  const std::string after = read_text(sw / "sweep.csv");
  EXPECT_NE(after.find("case_0001,ok,"), std::string::npos) << after;
  EXPECT_NE(after.find("case_0002,\"fault: body 'block'"), std::string::npos) << after;
}

// --pull-off pulls each finished case off into its pull-off/ and adds its results to the table;
// a case that cannot be pulled off (here: run without bonding) leaves the reason in
// pull-off-error.txt, and the sweep goes on; run again, the pulled cases are not pulled again.
TEST(Cli, SweepPullsOffItsCases) {
  const std::string dir = make_temp_dir();
  const std::string sweep = "sweep '" + std::string(COLDSPRAY_SOURCE_DIR) +
                            "/examples/verification/bonding-impact.yaml' --out sw --quiet "
                            "--vary bonding.model=none,energy --set solver.end_time=0.3ns "
                            "--pull-off";
  const auto first = run_coldspray(sweep, dir);
  ASSERT_EQ(first.status, 0) << first.output;
  const fs::path sw = fs::path(dir) / "sw";
  EXPECT_NE(read_text(sw / "case_0001" / "pull-off-error.txt").find("was run without bonding"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(sw / "case_0002" / "pull-off" / "summary.json"));
  const std::string table = read_text(sw / "sweep.csv");
  EXPECT_NE(table.find(",pull_off.peak_force,pull_off.work_of_separation,pull_off.bonded_area,"
                       "pull_off.projected_area,pull_off.strength_bonded,"
                       "pull_off.strength_projected,pull_off.separated\n"),
            std::string::npos)
      << table;
  const auto stamp = fs::last_write_time(sw / "case_0002" / "pull-off" / "summary.json");
  const auto again = run_coldspray(sweep, dir);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(fs::last_write_time(sw / "case_0002" / "pull-off" / "summary.json"), stamp);
}

// Under mpirun the cases are shared among the ranks (rank r runs cases i % ranks == r) and rank 0
// writes the table. Skipped where OpenMPI's launcher is not installed.
TEST(Cli, SweepSpreadsCasesOverMpiRanks) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  const std::string dir = make_temp_dir();
  const std::string command =
      "cd '" + dir +
      "' && ASAN_OPTIONS=detect_leaks=0 mpirun -x ASAN_OPTIONS --allow-run-as-root "
      "--oversubscribe -np 2 '" +
      COLDSPRAY_BINARY + "' " + kSweep.substr(0, kSweep.find("--jobs")) +
      "--threads-per-job 1 --vary 'bodies.block.velocity=[0, 0, 1 m/s],[0, 0, 2 m/s]' "
      "> out.txt 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(fs::path(dir) / "out.txt");
  const std::string out = read_text(fs::path(dir) / "out.txt");
  EXPECT_NE(out.find("rank 0/2: 2 cases, 1 run now"), std::string::npos) << out;
  EXPECT_NE(out.find("rank 1/2: 2 cases, 1 run now"), std::string::npos) << out;
  const std::string table = read_text(fs::path(dir) / "sw" / "sweep.csv");
  EXPECT_NE(table.find("case_0001,ok,"), std::string::npos) << table;
  EXPECT_NE(table.find("case_0002,ok,"), std::string::npos) << table;
}

TEST(Cli, SweepRejectsABadVariationBeforeRunning) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("sweep '" + std::string(COLDSPRAY_TEST_DATA) +
                                   "/cli/escape.yaml' --out sw --vary 'solver.cfl=0.3,2'",
                               dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("solver.cfl"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(fs::path(dir) / "sw"));
}

}  // namespace
}  // namespace coldspray::cli
