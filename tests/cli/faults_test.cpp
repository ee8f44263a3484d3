// Faults that cannot pass as ok (docs/reliability.md): issue 24's broken runs stop with exit 3,
// the diagnostic, a last snapshot, a summary with the fault as status, and tables that end at the
// fault time; the verdict does not depend on the output settings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "read_text.hpp"
#include "run_command.hpp"
#include "table.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

const std::string kBondingImpact =
    std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/bonding-impact.yaml";

struct FaultedRun {
  CommandResult r;
  fs::path out;
  nlohmann::json summary;
};

// `coldspray run bonding-impact.yaml SETS --out result` in a fresh folder.
FaultedRun run_bonding_impact(const std::string& sets) {
  const std::string dir = make_temp_dir("faults");
  FaultedRun f;
  f.r = run_coldspray("run '" + kBondingImpact + "' " + sets + " --out result --quiet --threads 1",
                      dir);
  f.out = fs::path(dir) / "result";
  std::ifstream in(f.out / "summary.json");
  if (in) f.summary = nlohmann::json::parse(in);
  return f;
}

// Issue 24's reproducer: the absorbing faces go unstable on a grid cell coarser than the bodies.
const std::string kUnstableAbsorbingFaces = "--set grid.cell_size=20um --set solver.end_time=10ns";

TEST(Faults, UnstableAbsorbingFacesStopWithStatus3AtTheFirstCheck) {
  const FaultedRun f = run_bonding_impact(kUnstableAbsorbingFaces);
  EXPECT_EQ(f.r.status, 3) << f.r.output;
  EXPECT_NE(f.r.output.find("fault: body 'substrate': mean velocity"), std::string::npos)
      << f.r.output;
  ASSERT_TRUE(f.summary.is_object()) << f.r.output;
  const std::string status = f.summary["status"];
  EXPECT_EQ(status.rfind("fault: body 'substrate': mean velocity", 0), 0u) << status;
  EXPECT_EQ(f.summary["steps"], 10);
  // The last snapshot, at the fault's step, listed in the collection.
  EXPECT_TRUE(fs::exists(f.out / "snapshots/step_00000010.vtu"));
  const std::string collection = read_text(f.out / "snapshots.pvd");
  EXPECT_NE(collection.find("snapshots/step_00000010.vtu"), std::string::npos) << collection;
  // And the checkpoint of the state at the fault (docs/reliability.md).
  EXPECT_TRUE(fs::exists(f.out / "checkpoints/step_00000010.h5"));
}

// It aborted (SIGABRT): the contact storage's overflow was thrown inside the parallel mapping.
// Nine bodies that reach one node mid-run stop the run with status 3, the diagnostic, a last
// snapshot and a checkpoint.
TEST(Faults, MoreBodiesAtANodeThanTheContactHoldsStopWithStatus3) {
  const std::string dir = make_temp_dir("faults");
  const auto r =
      run_coldspray("run '" + std::string(COLDSPRAY_TEST_DATA) +
                        "/cli/nine-bodies-converge.yaml' --out result --quiet --threads 2",
                    dir);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("fault: more than 8 bodies meet at grid node"), std::string::npos)
      << r.output;
  const fs::path out = fs::path(dir) / "result";
  std::ifstream in(out / "summary.json");
  ASSERT_TRUE(in) << r.output;
  const std::string status = nlohmann::json::parse(in)["status"];
  EXPECT_EQ(status.rfind("fault: more than 8 bodies meet at grid node", 0), 0u) << status;
  int snapshots = 0;
  for (const auto& f : fs::directory_iterator(out / "snapshots")) snapshots += f.is_regular_file();
  EXPECT_EQ(snapshots, 2);  // t = 0 and the fault's
  EXPECT_FALSE(fs::is_empty(out / "checkpoints"));
}

// The checks run every kFaultCheckStride steps, not when a history row falls due: rows at every
// step or every 5 ns, the run faults at the same step with the same diagnostic, and its history
// ends with a row at the fault time either way.
TEST(Faults, TheVerdictDoesNotDependOnTheHistoryInterval) {
  const FaultedRun every_step =
      run_bonding_impact(kUnstableAbsorbingFaces + " --set output.history_interval=0");
  const FaultedRun sparse =
      run_bonding_impact(kUnstableAbsorbingFaces + " --set output.history_interval=5ns");
  for (const FaultedRun* f : {&every_step, &sparse}) {
    EXPECT_EQ(f->r.status, 3) << f->r.output;
    ASSERT_TRUE(f->summary.is_object()) << f->r.output;
    const Table history = read_table((f->out / "history.csv").string());
    ASSERT_FALSE(history.rows.empty());
    EXPECT_NEAR(history.values("time").back(), f->summary["time"].get<double>(), 1e-18);
  }
  EXPECT_EQ(every_step.summary["steps"], sparse.summary["steps"]);
  EXPECT_EQ(every_step.summary["status"], sparse.summary["status"]);
  // Rows at every step: t = 0 and the ten steps; every 5 ns: t = 0, 5 ns, and the fault.
  EXPECT_EQ(read_table((every_step.out / "history.csv").string()).rows.size(), 11u);
  EXPECT_EQ(read_table((sparse.out / "history.csv").string()).rows.size(), 3u);
}

// A specific heat that underflows the heating makes temperatures inf while the energy budget
// stays finite: once ran to "max T inf K" with status ok.
TEST(Faults, AnInfiniteTemperatureStopsWithStatus3) {
  const FaultedRun f = run_bonding_impact(
      "--set 'materials.soft={base: al-ptw, specific_heat: 5e-324 J/kg/K}' "
      "--set bodies.substrate.material=soft --set solver.end_time=10ns");
  EXPECT_EQ(f.r.status, 3) << f.r.output;
  EXPECT_NE(f.r.output.find("fault: body 'substrate', point"), std::string::npos) << f.r.output;
  EXPECT_NE(f.r.output.find("temperature inf K"), std::string::npos) << f.r.output;
  ASSERT_TRUE(f.summary.is_object()) << f.r.output;
  const std::string status = f.summary["status"];
  EXPECT_NE(status.find("temperature inf K"), std::string::npos) << status;
  EXPECT_EQ(f.summary["steps"].get<long>() % 10, 0);
}

}  // namespace
}  // namespace coldspray::testing
