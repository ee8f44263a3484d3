// solver.stop_when_separated (run/step_rule.hpp, docs/bonding.md "Stopping once separated"): the
// coarse Cu impact at 500 m/s (examples/verification/pd-quarter-impact.yaml) leaves the substrate's
// contact at 26.3 ns; stopped one verdict window later, its particle's velocity is the run to 60
// ns's to round-off, since nothing but contact changes a free body's momentum.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json summary(const fs::path& run) {
  std::ifstream in(run / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(StopWhenSeparated, EndsOneWindowAfterTheParticleLeavesWithItsFinalVelocity) {
  const fs::path dir = make_temp_dir();
  const std::string run = "run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                          "/examples/verification/pd-quarter-impact.yaml' --quiet "
                          "--set solver.end_time=60ns --out ";
  const auto stopped = run_coldspray(run + "stopped --set solver.stop_when_separated=true", dir);
  ASSERT_EQ(stopped.status, 0) << stopped.output;
  const auto full = run_coldspray(run + "full", dir);
  ASSERT_EQ(full.status, 0) << full.output;

  const nlohmann::json s = summary(dir / "stopped"), f = summary(dir / "full");
  const double since = s["system"]["separated_since"].get<double>();
  EXPECT_GT(since, 20e-9);  // after the rebound (the particle is in contact from 0 to about 25 ns)
  EXPECT_NEAR(s["time"].get<double>(), since + 20e-9, 1e-15);
  EXPECT_TRUE(f["system"]["separated_since"].is_null());
  EXPECT_DOUBLE_EQ(f["time"].get<double>(), 60e-9);

  const double v_stopped = s["bodies"]["particle"]["velocity"][2].get<double>();
  const double v_full = f["bodies"]["particle"]["velocity"][2].get<double>();
  EXPECT_GT(v_full, 100.0);  // the coarse impact's rebound, 125 m/s
  EXPECT_NEAR(v_stopped, v_full, 1e-9 * v_full);
  EXPECT_EQ(s["bodies"]["particle"]["verdict"]["outcome"], "rebounded");
}

}  // namespace
}  // namespace coldspray::testing
