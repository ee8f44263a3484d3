// The calibration's pieces that are not already the math's: classification by the runs' verdicts
// or by tolerances (thesis eqs 4.8-4.9, §5.1.2), parameter grids with linear and log spacing, the
// run folders, and the analysis of runs on disk: the calibrated pair where two sizes' boundaries
// cross or, where they do not, at the midpoint of their closest approach, with undecided runs
// left out.
#include "studies/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "read_text.hpp"
#include "temp_dir.hpp"

namespace coldspray::studies {
namespace {

// By default a run is classified by its verdict; undecided runs, and runs whose summary has no
// verdict, are left out.
TEST(Classification, ByTheVerdict) {
  const Classification rule;
  EXPECT_EQ(classify(rule, {"bonded", 0.04, 0.0, 0.0}), 1);  // the tolerances are not looked at
  EXPECT_EQ(classify(rule, {"rebounded", 0.0, 1.0, 50.0}), 0);
  EXPECT_EQ(classify(rule, {"undecided", 0.0, 1.0, 50.0}), kLeftOut);
  EXPECT_EQ(classify(rule, {"", 0.0, 1.0, 50.0}), kLeftOut);
  EXPECT_EQ(describe(rule), "by the runs' verdicts");
}

TEST(Classification, CorAndPbcpBothMustPass) {
  Classification rule;  // cor <= 0.003, pbcp >= 5 %
  rule.by = Classification::By::CorPbcp;
  EXPECT_EQ(classify(rule, {"", 0.001, 0.0, 5.0}), 1);
  EXPECT_EQ(classify(rule, {"", 0.003, 0.0, 72.0}), 1);
  EXPECT_EQ(classify(rule, {"", -0.2, 0.0, 50.0}), 1);  // still moving into the substrate
  EXPECT_EQ(classify(rule, {"", 0.0031, 0.0, 72.0}), 0);
  EXPECT_EQ(classify(rule, {"", 0.001, 1.0, 4.9}), 0);          // abp is not looked at
  EXPECT_EQ(classify(rule, {"bonded", 0.0031, 0.0, 72.0}), 0);  // nor the verdict
  EXPECT_EQ(classify(rule, {"", NAN, 0.0, 72.0}), 0);
  EXPECT_EQ(classify(rule, {"", 0.0, 0.0, NAN}), 0);
}

TEST(Classification, CorAndAbpAsEq48) {
  Classification rule;
  rule.by = Classification::By::CorAbp;
  rule.cor_max = 0.002;
  rule.abp_min = 0.15;  // thesis eq 4.8, the 14 um particle
  EXPECT_EQ(classify(rule, {"", 0.002, 0.15, 0.0}), 1);
  EXPECT_EQ(classify(rule, {"", 0.002, 0.149, 100.0}), 0);
  EXPECT_EQ(classify(rule, {"", 0.0021, 0.5, 100.0}), 0);
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

// Writes, for every run of `plan`, the summary.json of a particle that sticks (verdict bonded,
// cor 0, pbcp 50 %) where bonds(size, x1, x2), and rebounds (rebounded, cor 0.04, pbcp 0)
// elsewhere, but undecided where undecided(x1, x2); analyses the runs.
std::vector<GridResult> analyse_synthetic(
    const CalibrationPlan& plan, const std::function<bool(std::size_t, double, double)>& bonds,
    const std::string& tag, std::string* json = nullptr,
    const std::function<bool(double, double)>& undecided = [](double, double) { return false; },
    std::string* runs_csv = nullptr) {
  const std::filesystem::path dir = testing::make_temp_dir("calibration-" + tag);
  for (const CalibrationRun& run : calibration_runs(plan, dir)) {
    std::filesystem::create_directories(run.folder);
    const bool stuck = bonds(run.size, run.x1, run.x2);
    const char* outcome = undecided(run.x1, run.x2) ? "undecided" : stuck ? "bonded" : "rebounded";
    std::ofstream(run.folder / "summary.json")
        << R"({"status": "ok", "bodies": {"particle": {"cor": )" << (stuck ? 0.0 : 0.04)
        << R"(, "abp": 1, "pbcp": )" << (stuck ? 50.0 : 0.0)
        << R"(, "v_rest": 0, "verdict": {"outcome": ")" << outcome
        << R"(", "separation_speed": 0.5, "margin": 1.5}}}})";
  }
  const std::vector<GridResult> results = analyse_calibration(plan, dir, tag);
  if (json) *json = testing::read_text(dir / "calibration.json");
  if (runs_csv) *runs_csv = testing::read_text(dir / "runs.csv");
  return results;
}

CalibrationPlan unit_square_plan() {
  CalibrationPlan plan;
  plan.grids = {"1um/0.25um"};
  plan.sizes = {{14e-6, 810.0, {}}, {30e-6, 770.0, {}}};
  plan.x1 = {"critical_energy", "J/m^2", 0.0, 1.0, 9, false};
  plan.x2 = {"critical_energy_rate", "J/m^2/s", 0.0, 1.0, 9, false};
  return plan;
}

// Size 0 bonds below the line x2 = x1, size 1 below x2 = 1 - x1: they cross at (0.5, 0.5).
TEST(CalibrationAnalysis, CrossingBoundariesGiveTheIntersection) {
  std::string json;
  const auto results = analyse_synthetic(
      unit_square_plan(),
      [](std::size_t size, double x1, double x2) { return size == 0 ? x2 < x1 : x2 < 1.0 - x1; },
      "cross", &json);
  ASSERT_EQ(results.size(), 1u);
  ASSERT_TRUE(results[0].calibrated.has_value()) << results[0].diagnosis;
  EXPECT_NEAR((*results[0].calibrated)[0], 0.5, 0.07);  // half a parameter step
  EXPECT_NEAR((*results[0].calibrated)[1], 0.5, 0.07);
  EXPECT_EQ(results[0].intersections.size(), 1u);
  EXPECT_TRUE(results[0].diagnosis.empty());
  EXPECT_NE(json.find(R"("calibrated_by": "intersection")"), std::string::npos) << json;
}

// Size 0 bonds for x1 < 0.3, size 1 for x1 < 0.7: parallel boundaries near x1 = 0.31 and 0.69
// (midway between the last bonded and first not bonded runs), no crossing; the compromise is
// their closest approach's midpoint, x1 = 0.5.
TEST(CalibrationAnalysis, ParallelBoundariesGiveTheClosestApproachMidpoint) {
  std::string json;
  const auto results = analyse_synthetic(
      unit_square_plan(),
      [](std::size_t size, double x1, double) { return x1 < (size == 0 ? 0.3 : 0.7); }, "apart",
      &json);
  ASSERT_EQ(results.size(), 1u);
  const GridResult& g = results[0];
  EXPECT_TRUE(g.intersections.empty());
  ASSERT_TRUE(g.closest.has_value());
  EXPECT_NEAR(g.closest->on_a[0], 0.3125, 0.03);
  EXPECT_NEAR(g.closest->on_b[0], 0.6875, 0.03);
  EXPECT_NEAR(g.closest->distance, 0.375, 0.05);
  ASSERT_TRUE(g.calibrated.has_value());
  EXPECT_NEAR((*g.calibrated)[0], 0.5, 0.02);
  EXPECT_NE(g.diagnosis.find("closest approach"), std::string::npos) << g.diagnosis;
  EXPECT_NE(json.find(R"("calibrated_by": "closest approach")"), std::string::npos) << json;
}

// The crossing case with the runs at x1 = 1/8 undecided: they are left out of the fit, counted,
// and listed in runs.csv with an empty y; the boundaries, fitted on the rest, still cross near
// (0.5, 0.5).
TEST(CalibrationAnalysis, UndecidedRunsAreLeftOutAndCounted) {
  std::string json, runs;
  const auto results = analyse_synthetic(
      unit_square_plan(),
      [](std::size_t size, double x1, double x2) { return size == 0 ? x2 < x1 : x2 < 1.0 - x1; },
      "undecided", &json, [](double x1, double) { return x1 == 0.125; }, &runs);
  ASSERT_EQ(results.size(), 1u);
  for (const SizeResult& r : results[0].sizes) {
    EXPECT_EQ(r.runs, 81u);
    EXPECT_EQ(r.undecided, 9u);  // one column of 9
    EXPECT_EQ(r.bonded + r.not_bonded, 72u);
    EXPECT_EQ(r.failed, 0u);
  }
  ASSERT_TRUE(results[0].calibrated.has_value()) << results[0].diagnosis;
  EXPECT_NEAR((*results[0].calibrated)[0], 0.5, 0.07);
  EXPECT_NE(json.find(R"("undecided": 9)"), std::string::npos) << json;
  EXPECT_NE(runs.find(",0.125,0,ok,undecided,0.5,1.5,"), std::string::npos) << runs;
  EXPECT_NE(runs.find(",0.125,1,ok,undecided,0.5,1.5,0.04,1,0,0,\n"), std::string::npos) << runs;
}

}  // namespace
}  // namespace coldspray::studies
