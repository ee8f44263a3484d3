// The calibration file (setups/calibration_file.hpp): every shipped one reads and makes valid
// cases, and its debond section reaches them.
#include "setups/calibration_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "read_text.hpp"
#include "temp_dir.hpp"

namespace coldspray::setups {
namespace {

namespace fs = std::filesystem;

const std::string kCalibration = std::string(COLDSPRAY_TEST_DATA) + "/cli/calibrate-tiny.yaml";

// The shipped calibration files read without error, and every run they would make is a valid
// case (checked as `coldspray check` checks a case file), without running any.
TEST(CalibrationFile, EveryExampleCalibrationMakesValidCases) {
  const fs::path examples = fs::path(COLDSPRAY_SOURCE_DIR) / "examples" / "calibration";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const CalibrationFile file = read_calibration_file(entry.path().string());
    if (file.activation) {  // calibrates: critical-penetration, two speeds per grid and size
      const auto runs = studies::activation_runs(activation_plan(file), "out");
      EXPECT_EQ(runs.size(), 2 * file.plan.grids.size() * file.plan.sizes.size()) << entry.path();
      for (const auto& run : runs) EXPECT_NO_THROW(activation_case(file, run)) << run.folder;
      continue;
    }
    const auto runs = studies::calibration_runs(file.plan, "out");
    EXPECT_EQ(runs.size(), file.plan.grids.size() * file.plan.sizes.size() *
                               static_cast<std::size_t>(file.plan.x1.count * file.plan.x2.count))
        << entry.path();
    for (const auto& run : runs) EXPECT_NO_THROW(calibration_case(file, run)) << run.folder;
  }
  EXPECT_GE(files, 3);
}

// A calibration file's `debond` section is its cases' bonding.debond: the calibration can be run
// with the debonding law on (docs/studies.md); unset, the law stays off.
TEST(CalibrationFile, TheCalibrationFilesDebondReachesItsCases) {
  const fs::path dir = testing::make_temp_dir();
  std::string text = testing::read_text(kCalibration);
  const CalibrationFile off = read_calibration_file(kCalibration);
  const auto runs = studies::calibration_runs(off.plan, "out");
  EXPECT_EQ(calibration_case(off, runs.front()).bonding.debond.law, case_file::DebondLaw::None);
  text.replace(text.find("end_time: 3 ns"), 14,
               "end_time: 3 ns\ndebond: {law: cohesive, strength: 50 MPa}");
  std::ofstream(dir / "calib.yaml") << text;
  const CalibrationFile on = read_calibration_file((dir / "calib.yaml").string());
  const case_file::Case c = calibration_case(on, runs.front());
  EXPECT_EQ(c.bonding.debond.law, case_file::DebondLaw::Cohesive);
  EXPECT_EQ(c.bonding.debond.strength, 50e6);
}

}  // namespace
}  // namespace coldspray::setups
