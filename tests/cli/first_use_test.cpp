// The first-use guards of the command line (docs/reliability.md, "First-use guards"): an unknown
// option named with the one meant, no bare number for a length, speed or time, a measured ETA,
// sizes printed in the unit of the case.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.hpp"
#include "source_paths.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

const std::string kTaylorBar =
    std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/taylor-bar-axisymmetric.yaml";

// `--diameter 20` was 20 m: the run sat silent allocating 1e15 points.
TEST(FirstUseGuards, ABareNumberForALengthSpeedOrTimeIsRefused) {
  const std::string dir = make_temp_dir();
  const std::string base = "impact --material al-ptw --out result --quiet ";
  const auto diameter = run_coldspray(base + "--diameter 20 --velocity 700m/s", dir);
  EXPECT_EQ(diameter.status, 2) << diameter.output;
  EXPECT_TRUE(has(diameter,
                  "error: --diameter: '20' has no unit: give the length with its unit, "
                  "e.g. '20um'"))
      << diameter.output;
  const auto speed = run_coldspray(base + "--diameter 20um --velocity 700", dir);
  EXPECT_EQ(speed.status, 2) << speed.output;
  EXPECT_TRUE(has(speed, "error: --velocity: '700' has no unit")) << speed.output;
  const auto time = run_coldspray(base + "--diameter 20um --velocity 700m/s --end-time 80", dir);
  EXPECT_EQ(time.status, 2) << time.output;
  EXPECT_TRUE(has(time, "error: --end-time: '80' has no unit")) << time.output;
  const auto grid = run_coldspray(base + "--diameter 20um --velocity 700m/s --grid 0.7/0.175", dir);
  EXPECT_EQ(grid.status, 2) << grid.output;
  EXPECT_TRUE(has(grid, "error: --grid: '0.7' has no unit")) << grid.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// It said "--velocity is required", or "The following arguments were not expected".
TEST(FirstUseGuards, AnUnknownOptionIsNamedWithTheOneMeant) {
  const auto speed =
      run_coldspray("impact --material al-ptw --diameter 20um --speed 700m/s --out result");
  EXPECT_EQ(speed.status, 2) << speed.output;
  EXPECT_TRUE(has(speed, "error: unknown option --speed; did you mean --velocity?"))
      << speed.output;
  const auto typo =
      run_coldspray("impact --material al-ptw --diamter 20um --velocity 700m/s --out result");
  EXPECT_EQ(typo.status, 2) << typo.output;
  EXPECT_TRUE(has(typo, "error: unknown option --diamter; did you mean --diameter?"))
      << typo.output;
  const auto other = run_coldspray("check '" + kExample + "' --frobnicate");
  EXPECT_EQ(other.status, 2) << other.output;
  EXPECT_TRUE(has(other, "error: unknown option --frobnicate (coldspray check --help lists"))
      << other.output;
}

// It printed the Taylor bar's radius as 3200 um.
TEST(FirstUseGuards, CheckPrintsSizesInTheUnitOfTheCase) {
  const auto bar = run_coldspray("check '" + kTaylorBar + "'");
  EXPECT_EQ(bar.status, 0) << bar.output;
  EXPECT_TRUE(has(bar, "cylinder r = 3.2 mm, h = 32.4 mm")) << bar.output;
  EXPECT_TRUE(has(bar, "spacing 0.2 mm")) << bar.output;
  EXPECT_TRUE(has(bar, "grid cell 0.4 mm")) << bar.output;
  const auto particle = run_coldspray("check '" + kExample + "'");
  EXPECT_EQ(particle.status, 0) << particle.output;
  EXPECT_TRUE(has(particle, "sphere r = 7 um")) << particle.output;
  EXPECT_TRUE(has(particle, "spacing 0.175 um")) << particle.output;
}

// The first ETA came from the first step alone, which pays for first touches of memory.
TEST(FirstUseGuards, TheFirstProgressLineWaitsForMeasuredSteps) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "run '" + kExample + "' --set solver.end_time=0.1ns --out result --threads 1", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r, "step 1  dt")) << r.output;
  EXPECT_TRUE(has(r, "ETA --")) << r.output;
}

}  // namespace
}  // namespace coldspray::testing
