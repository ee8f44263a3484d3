// The calibration's pieces that are not already the math's: classification by tolerances (thesis
// eqs 4.8-4.9, §5.1.2), parameter grids with linear and log spacing, and the run folders.
#include "studies/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::studies {
namespace {

TEST(Classification, CorAndPbcpBothMustPass) {
  const Classification rule;  // cor <= 0.003, pbcp >= 5 %
  EXPECT_EQ(classify(rule, 0.001, 0.0, 5.0), 1);
  EXPECT_EQ(classify(rule, 0.003, 0.0, 72.0), 1);
  EXPECT_EQ(classify(rule, -0.2, 0.0, 50.0), 1);  // still moving into the substrate
  EXPECT_EQ(classify(rule, 0.0031, 0.0, 72.0), 0);
  EXPECT_EQ(classify(rule, 0.001, 1.0, 4.9), 0);  // abp is not looked at
  EXPECT_EQ(classify(rule, NAN, 0.0, 72.0), 0);
  EXPECT_EQ(classify(rule, 0.0, 0.0, NAN), 0);
}

TEST(Classification, CorAndAbpAsEq48) {
  Classification rule;
  rule.by = Classification::By::CorAbp;
  rule.cor_max = 0.002;
  rule.abp_min = 0.15;  // thesis eq 4.8, the 14 um particle
  EXPECT_EQ(classify(rule, 0.002, 0.15, 0.0), 1);
  EXPECT_EQ(classify(rule, 0.002, 0.149, 100.0), 0);
  EXPECT_EQ(classify(rule, 0.0021, 0.5, 100.0), 0);
  EXPECT_EQ(describe(rule), "cor <= 0.002 and abp >= 0.15");
}

TEST(ParameterValues, LinearIncludesBothEnds) {
  const auto v = parameter_values({"critical_energy", "J/m^2", 200.0, 3000.0, 5, false});
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v.front(), 200.0);
  EXPECT_EQ(v.back(), 3000.0);
  EXPECT_DOUBLE_EQ(v[1], 900.0);
  EXPECT_DOUBLE_EQ(v[2], 1600.0);
}

TEST(ParameterValues, LogIsEvenInLog10) {
  const auto v = parameter_values({"critical_energy_rate", "J/m^2/s", 1e4, 1e9, 6, true});
  ASSERT_EQ(v.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(std::log10(v[i]), 4.0 + i, 1e-12) << i;
  EXPECT_EQ(v.front(), 1e4);
  EXPECT_EQ(v.back(), 1e9);
  EXPECT_EQ(parameter_values({"x", "-", 3.0, 4.0, 1, false}), std::vector<double>{3.0});
  EXPECT_THROW(parameter_values({"x", "-", -1.0, 4.0, 3, true}), std::invalid_argument);
}

TEST(CalibrationRuns, OneFolderPerGridSizeAndParameters) {
  CalibrationPlan plan;
  plan.grids = {"0.7um/0.175um", "1um/0.25um"};
  plan.sizes = {{14e-6, 810.0, {}}, {30e-6, 770.0, {}}};
  plan.x1 = {"critical_energy", "J/m^2", 200.0, 3000.0, 2, false};
  plan.x2 = {"critical_energy_rate", "J/m^2/s", 1e4, 1e9, 3, true};
  const auto runs = calibration_runs(plan, "out");
  ASSERT_EQ(runs.size(), 2u * 2u * 2u * 3u);
  EXPECT_EQ(runs.front().folder, "out/0.7um-0.175um/14um-v810ms/p200_10000");
  EXPECT_EQ(runs.back().folder, "out/1um-0.25um/30um-v770ms/p3000_1e+09");
  EXPECT_EQ(runs.back().grid, 1u);
  EXPECT_EQ(runs.back().size, 1u);
}

}  // namespace
}  // namespace coldspray::studies
