// `coldspray vcrit` and `coldspray calibrate` on tiny cases: the tables they write, reruns that
// reuse the runs on disk, a calibration with one class only diagnosed, and the calibration file's
// input errors (exit 2 with FILE:LINE and the key).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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

std::size_t count_entries(const fs::path& folder) {
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(folder)) n += e.is_directory() ? 1 : 0;
  return n;
}

// A 4 um particle on a 1 um grid for 3 ns with the thesis' energy parameters, model (no
// activation) and set-up. At 3 ns nothing has
// come to rest, so the verdict is read over the last 1 ns with a threshold of 50 m/s to make the
// search bracket: from 200 m/s (no point bonds: rebounded) to 1200 m/s (bonded after two
// extensions to 5 ns); the test is of the search's machinery, not of the physics.
const std::string kVcrit =
    "vcrit --material al-ptw --diameters 4um --grid 1um/0.5um --end-time 3ns --vmin 200m/s "
    "--tol 100m/s --Gc 1503.74J/m^2 --Gc-rate 2.271J/m^2/us --threads-per-job 1 --out vc "
    "--setup thesis --set bonding.critical_penetration=0 "
    "--set metrics.verdict_window=1ns --set metrics.bonded_separation_speed=50m/s";

TEST(CliStudies, VcritWritesItsTableAndReusesItsRuns) {
  const std::string dir = make_temp_dir();
  const auto first = run_coldspray(kVcrit, dir);
  ASSERT_EQ(first.status, 0) << first.output;
  const fs::path vc = fs::path(dir) / "vc";
  const std::string table = read_text(vc / "vcrit.csv");
  EXPECT_EQ(table.rfind("diameter_um,vcrit_ms,lower_ms,margin,lower_margin,lower_outcome,pbcp,"
                        "v_rest,runs_used,undecided,status\n",
                        0),
            0u)
      << table;
  EXPECT_NE(table.find(",found\n"), std::string::npos) << table;
  const std::string runs = read_text(vc / "vcrit_runs.csv");
  EXPECT_EQ(runs.rfind("diameter_um,velocity_ms,status,outcome,bonded,separation_speed,margin,"
                       "extensions,cor,v_rest,abp,pbcp\n",
                       0),
            0u)
      << runs;
  EXPECT_NE(runs.find("4,200,ok,rebounded,0,"), std::string::npos) << runs;
  EXPECT_NE(runs.find("4,1200,ok,bonded,1,"), std::string::npos) << runs;
  // The progress line: after every impact, and once the diameter is settled.
  EXPECT_NE(first.output.find("vcrit: 0/1 diameters, 1 impacts (1 simulated)"), std::string::npos)
      << first.output;
  EXPECT_NE(first.output.find("d 4 um at 200 m/s rebounded"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("vcrit: 1/1 diameters"), std::string::npos) << first.output;
  const std::size_t folders = count_entries(vc);

  const auto again = run_coldspray(kVcrit + " --quiet", dir);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("0 impacts simulated now"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("vcrit: "), std::string::npos) << again.output;
  EXPECT_EQ(read_text(vc / "vcrit.csv"), table);  // runs_used and all else unchanged
  EXPECT_EQ(count_entries(vc), folders);
}

TEST(CliStudies, VcritRejectsABadRange) {
  const auto r = run_coldspray(
      "vcrit --material al-ptw --diameters 4um --grid 1um/0.5um --vmin 900m/s --vmax 800m/s");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--vmax"), std::string::npos) << r.output;
  const auto unit = run_coldspray("vcrit --material al-ptw --diameters 4kg --grid 1um/0.5um");
  EXPECT_EQ(unit.status, 2) << unit.output;
  EXPECT_NE(unit.output.find("--diameters"), std::string::npos) << unit.output;
}

const std::string kCalibration = std::string(COLDSPRAY_TEST_DATA) + "/cli/calibrate-tiny.yaml";

// Every run of the tiny calibration bonds (pbcp > 5 %, cor < 0 at 3 ns): one class per size,
// which is diagnosed, with the runs kept and exit status 0.
TEST(CliStudies, CalibrateWritesRunsAndDiagnosesOneClass) {
  const std::string dir = make_temp_dir();
  const std::string command = "calibrate '" + kCalibration +
                              "' --out cal --quiet --jobs 2 "
                              "--threads-per-job 1";
  const auto r = run_coldspray(command, dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("8 impacts, 8 run now (0 failed)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("one class only (4 bonded, 0 not bonded)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("not calibrated"), std::string::npos) << r.output;
  const fs::path cal = fs::path(dir) / "cal";
  const std::string runs = read_text(cal / "runs.csv");
  EXPECT_EQ(runs.rfind("grid,size,diameter_um,velocity_ms,critical_energy,critical_energy_rate,"
                       "status,outcome,separation_speed,margin,cor,abp,pbcp,v_rest,y\n",
                       0),
            0u)
      << runs;
  EXPECT_NE(runs.find("1um/0.5um,6um,6,1000,3000,1000000000,ok,"), std::string::npos) << runs;
  const std::string json = read_text(cal / "calibration.json");
  EXPECT_NE(json.find("\"calibrated\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("one class only"), std::string::npos) << json;

  const auto again = run_coldspray(command, dir);
  EXPECT_NE(again.output.find("0 run now (0 failed), 8 finished before"), std::string::npos)
      << again.output;
}

// Classified by the runs' verdicts (the default, without `classify`), the tiny calibration's
// runs are all undecided after their two extensions, at 5 ns (the halves of their last 1 ns
// differ by 12-90 m/s, the particles still in the impact): left out of the fit, counted, listed
// with an empty y, and diagnosed.
TEST(CliStudies, CalibrateByTheVerdictLeavesUndecidedRunsOut) {
  const std::string dir = make_temp_dir();
  std::string text = read_text(kCalibration);
  const std::size_t line = text.find("classify:");
  text.erase(line, text.find('\n', line) - line);
  std::ofstream(fs::path(dir) / "calib.yaml") << text;
  const auto r =
      run_coldspray("calibrate calib.yaml --out cal --quiet --jobs 2 --threads-per-job 1", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(
      r.output.find("4 um at 1000 m/s: 4 runs, 0 bonded, 0 not bonded, 4 undecided (left out) "
                    "(by the runs' verdicts)"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("let undecided runs go on longer"), std::string::npos) << r.output;
  const std::string runs = read_text(fs::path(dir) / "cal" / "runs.csv");
  EXPECT_NE(runs.find("1um/0.5um,4um,4,1000,100,10000,ok,undecided,"), std::string::npos) << runs;
  EXPECT_NE(runs.find(",\n1um/0.5um,4um,4,1000,100,1000000000,ok,undecided,"), std::string::npos)
      << runs;  // the row before ends with an empty y
  const std::string json = read_text(fs::path(dir) / "cal" / "calibration.json");
  EXPECT_NE(json.find("\"undecided\": 4"), std::string::npos) << json;
  EXPECT_NE(json.find("\"by\": \"verdict\""), std::string::npos) << json;
}

// `calibrates: critical-penetration` (docs/studies.md): two runs per size, each size's power law
// p = p_c (v / v_c)^b, and the one critical penetration whose two predicted critical velocities
// err equally and oppositely in ln v; a `parameters` section is refused for it.
TEST(CliStudies, CalibratesTheActivationFromEachSizesPenetration) {
  const std::string dir = make_temp_dir();
  const std::string file = std::string(COLDSPRAY_TEST_DATA) + "/cli/activation-tiny.yaml";
  const auto r = run_coldspray("calibrate '" + file + "' --out cal --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("calibrated: critical_penetration = "), std::string::npos) << r.output;
  const auto j = nlohmann::json::parse(read_text(fs::path(dir) / "cal" / "calibration.json"));
  const auto& grid = j["grids"][0];
  ASSERT_TRUE(grid["critical_penetration"].is_number()) << j.dump(2);
  const double delta = grid["critical_penetration"].get<double>();
  double errors[2];
  for (int s = 0; s < 2; ++s) {
    const auto& size = grid["sizes"][s];
    const double p = size["penetration"].get<double>(), b = size["exponent"].get<double>();
    const double v = size["velocity_ms"].get<double>();
    EXPECT_GT(b, 0.3) << size.dump();
    EXPECT_NEAR(size["predicted_vcrit_ms"].get<double>(), v * std::pow(delta / p, 1.0 / b),
                1e-9 * v);
    errors[s] = std::log(size["predicted_vcrit_ms"].get<double>() / v);
  }
  EXPECT_NEAR(errors[0], -errors[1], 1e-9);
  const std::string runs = read_text(fs::path(dir) / "cal" / "runs.csv");
  EXPECT_NE(runs.find("D/8,4um,4,980,ok,"), std::string::npos) << runs;
  EXPECT_NE(runs.find("D/8,6um,6,969,ok,"), std::string::npos) << runs;

  std::ofstream(fs::path(dir) / "bad.yaml")
      << read_text(file)
      << "parameters:\n  critical_energy: {from: 1 J/m^2, to: 2 J/m^2, count: 2}\n";
  const auto bad = run_coldspray("calibrate bad.yaml --out bad", dir);
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.yaml:10:3: key 'parameters': is for calibrates: "
                            "bonding-parameters"),
            std::string::npos)
      << bad.output;
}

struct BadFile {
  const char* name;
  std::string from, to;  // a text edit of the tiny file
  std::string expected;  // in the message
};

TEST(CliStudies, CalibrationFileErrorsNameLineAndKey) {
  const std::string original = read_text(kCalibration);
  const BadFile cases[] = {
      {"unknown key", "end_time: 3 ns", "end_time: 3 ns\nend_tme: 4 ns",
       "calib.yaml:7:1: key 'end_tme': unknown key"},
      {"bad unit", "to: 3000 J/m^2,", "to: 3000 m/s,",
       "calib.yaml:11:42: key 'parameters.critical_energy.to'"},
      {"missing sizes",
       "sizes:\n  - {diameter: 4 um, velocity: 1000 m/s}\n  - {diameter: 6 um, velocity: 1000 "
       "m/s}\n",
       "", "key 'sizes'"},
      {"bad grid", "grid: 1um/0.5um", "grid: 1um", "calib.yaml:5:7: key 'grid'"},
      {"bad transform", "[identity, log10]", "[identity, log]", "key 'fit.transform'"},
      {"wrong model", "model: energy", "model: strain", "key 'parameters.critical_strain'"},
      {"retired metrics key", "{verdict_window: 1 ns}", "{bonded_rest_speed: 1 m/s}",
       "calib.yaml:15:11: key 'metrics.bonded_rest_speed': was removed"},
      {"a tolerance with the verdict", "{by: cor-pbcp,", "{by: verdict,",
       "calib.yaml:13:34: key 'classify.cor_max': is a tolerance of by: cor-pbcp or cor-abp"},
  };
  for (const BadFile& bad : cases) {
    const std::string dir = make_temp_dir();
    std::string text = original;
    const auto at = text.find(bad.from);
    ASSERT_NE(at, std::string::npos) << bad.name;
    text.replace(at, bad.from.size(), bad.to);
    std::ofstream(fs::path(dir) / "calib.yaml") << text;
    const auto r = run_coldspray("calibrate calib.yaml", dir);
    EXPECT_EQ(r.status, 2) << bad.name << "\n" << r.output;
    EXPECT_NE(r.output.find(bad.expected), std::string::npos) << bad.name << "\n" << r.output;
    EXPECT_FALSE(fs::exists(fs::path(dir) / "out")) << bad.name;
  }
}

}  // namespace
}  // namespace coldspray::cli
