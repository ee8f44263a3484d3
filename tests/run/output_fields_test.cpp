// The JSON outputs' declared fields (io/output_schema.hpp): the writer emits them in declared
// order and leaves out absent ones; docs/outputs.md's table for each file lists the same fields
// with the same units; and the files that have always had their keys in alphabetical order
// (vcrit_fit.json, both calibration.json) keep it.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io/output_schema.hpp"
#include "read_text.hpp"
#include "run/summary.hpp"
#include "studies/bulk_fracture_fit.hpp"
#include "studies/calibration_json.hpp"
#include "studies/critical_velocity.hpp"
#include "studies/deposit_json.hpp"
#include "studies/pull_off_fields.hpp"
#include "temp_dir.hpp"

namespace {

using Json = nlohmann::ordered_json;
using coldspray::io::FieldUnits;

struct Shot {
  double speed = 0.0;
  std::string name;
  bool has_name = false;
};

TEST(OutputSchema, WritesTheDeclaredFieldsInOrderAndLeavesOutAbsentOnes) {
  const coldspray::io::OutputFields<Shot> fields = {
      {"speed", "m/s", [](const Shot& s) { return Json(s.speed); }},
      {"name", "-",
       [](const Shot& s) { return s.has_name ? Json(s.name) : coldspray::io::absent_field(); }},
      {"length", "m", [](const Shot&) { return Json(2.5); },
       [](const Shot&) { return std::string("horizon"); }}};
  EXPECT_EQ(coldspray::io::write_fields(fields, Shot{810.0, "al", true}).dump(),
            R"({"speed":810.0,"name":"al","horizon":2.5})");
  EXPECT_EQ(coldspray::io::write_fields(fields, Shot{700.0, "", false}).dump(),
            R"({"speed":700.0,"horizon":2.5})");
}

// The rows of docs/outputs.md's table between "<!-- FILE fields -->" and its end marker.
FieldUnits doc_table(const std::string& file) {
  std::ifstream doc(std::string(COLDSPRAY_SOURCE_DIR) + "/docs/outputs.md");
  EXPECT_TRUE(doc) << "docs/outputs.md";
  FieldUnits table;
  bool in_table = false, ended = false;
  for (std::string line; std::getline(doc, line);) {
    if (line == "<!-- " + file + " fields -->") in_table = true;
    if (line == "<!-- end " + file + " fields -->") {
      ended = in_table;
      break;
    }
    if (!in_table || line.rfind("| ", 0) != 0 || line == "| field | unit |" ||
        line.rfind("| ---", 0) == 0)
      continue;
    const std::size_t bar = line.find(" | ", 2);
    table.emplace_back(line.substr(2, bar - 2), line.substr(bar + 3, line.size() - bar - 5));
  }
  EXPECT_TRUE(ended) << "docs/outputs.md has no table marked " << file;
  return table;
}

// Each JSON output's docs table against its declaration.
TEST(OutputFields, DocsTablesListTheDeclaredFieldsAndUnits) {
  const std::vector<std::pair<std::string, FieldUnits (*)()>> tables = {
      {"summary.json", coldspray::run::summary_field_units},
      {"pull-off summary.json", coldspray::studies::pull_off_field_units},
      {"deposit.json", coldspray::studies::deposit_field_units},
      {"vcrit_fit.json", coldspray::studies::vcrit_fit_field_units},
      {"calibration.json", coldspray::studies::calibration_field_units},
      {"activation calibration.json", coldspray::studies::activation_field_units},
      {"bulk-fracture fit.json", coldspray::studies::bulk_fracture_field_units}};
  for (const auto& [file, declared] : tables) {
    SCOPED_TRACE(file);
    EXPECT_EQ(doc_table(file), declared());
  }
}

// The file's text against the same parsed into nlohmann::json's sorted map and dumped again.
void expect_alphabetical(const std::string& path) {
  const std::string text = coldspray::testing::read_text(path);
  ASSERT_FALSE(text.empty()) << path;
  EXPECT_EQ(text, nlohmann::json::parse(text).dump(2) + "\n") << path;
}

TEST(OutputFields, VcritFitKeysStayAlphabetical) {
  const std::string dir = coldspray::testing::make_temp_dir("vcrit-fit");
  coldspray::studies::LinearFit fit;
  fit.a = 400.0;
  fit.b = -8.0;
  fit.r_squared = 0.9;
  fit.se_a = NAN;
  fit.n = 2;
  coldspray::studies::write_vcrit_fit(dir + "/vcrit_fit.json", fit);
  expect_alphabetical(dir + "/vcrit_fit.json");
}

// Two sizes whose labels sort the other way round ("5um" after "14um") and parameters with
// every optional part of a grid's result present, so every object's keys are written.
TEST(OutputFields, CalibrationKeysStayAlphabetical) {
  using namespace coldspray::studies;
  CalibrationPlan plan;
  plan.grids = {"0.7um/0.175um"};
  plan.x1 = {"critical_energy", "J/m^2", 0.1, 10.0, 3, true};
  plan.x2 = {"critical_energy_rate", "J/m^2/s", 1.0, 2.0, 2, false};
  plan.sizes.resize(2);
  plan.sizes[0].diameter = 5e-6;
  plan.sizes[0].velocity = 700.0;
  plan.sizes[0].classify.by = Classification::By::CorAbp;
  plan.sizes[1].diameter = 14e-6;
  plan.sizes[1].velocity = 600.0;
  plan.sizes[1].classify.by = Classification::By::CorPbcp;
  GridResult gr;
  gr.grid = plan.grids[0];
  gr.sizes.resize(2);
  gr.sizes[0].fit = LogisticFit{};
  gr.sizes[0].fit->theta = Eigen::VectorXd::Ones(6);
  gr.sizes[1].diagnosis = "too few runs";
  gr.intersections = {{1.0, 1.5}};
  gr.calibrated = std::array<double, 2>{1.0, 1.5};
  gr.closest = ClosestApproach{{1.0, 1.5}, {1.0, 1.5}, {1.0, 1.5}, 0.0};
  const std::string dir = coldspray::testing::make_temp_dir("calibration-json");
  write_calibration_json(plan, {gr}, dir, "quick");
  expect_alphabetical(dir + "/calibration.json");

  ActivationPlan activation{plan.grids, plan.sizes, 0.02};
  ActivationGridResult ar;
  ar.grid = plan.grids[0];
  ar.laws = {{1e-7, 2.0}, {2e-7, 1.5}};
  ar.predicted = {650.0, 610.0};
  ar.critical_penetration = 1.5e-7;
  write_activation_json(activation, {ar}, dir, "activation");
  expect_alphabetical(dir + "/calibration.json");
}

}  // namespace
