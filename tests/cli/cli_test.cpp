// The `coldspray` command line: exit statuses, messages that name the key, files written or not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "read_text.hpp"
#include "run_command.hpp"
#include "source_paths.hpp"
#include "table.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

TEST(Cli, VersionPrintsTheProjectVersion) {
  const auto r = run_coldspray("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find(std::string("coldspray ") + COLDSPRAY_VERSION), std::string::npos);
}

TEST(Cli, UnknownSubcommandIsBadInput) {
  const auto r = run_coldspray("frobnicate");
  EXPECT_EQ(r.status, 2) << r.output;
}

TEST(Cli, MaterialsListsTheBuiltIns) {
  const auto r = run_coldspray("materials");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* name : {"al-ptw", "al-jc", "cu-jc", "cu-ptw", "al6061-jc", "in718-jc", "ni-jc",
                           "ss316l-jc", "steel4340-jc", "ti64-jc"})
    EXPECT_NE(r.output.find(name), std::string::npos) << name;
  // Each with its description, in one column after the longest name.
  EXPECT_NE(r.output.find("steel4340-jc AISI 4340 steel (substrate)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("al-jc        Pure aluminium"), std::string::npos) << r.output;
}

TEST(Cli, MaterialsPrintsParametersAndSources) {
  const auto r = run_coldspray("materials al-ptw");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0.0115"), std::string::npos) << r.output;  // PTW y0, thesis Table 2.1
  EXPECT_NE(r.output.find("Table 2.1"), std::string::npos) << r.output;
}

TEST(Cli, UnknownMaterialIsBadInput) {
  const auto r = run_coldspray("materials unobtainium");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unobtainium"), std::string::npos) << r.output;
}

TEST(Cli, CheckAcceptsTheDefaultExample) {
  const auto r = run_coldspray("check '" + kExample + "'");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("OK"), std::string::npos) << r.output;
}

TEST(Cli, CaseSummarySaysAnUndecidedRunGoesOn) {
  const std::string line = "while a body is undecided the run goes on by up to 2 x 20 ns";
  const auto r = run_coldspray("check '" + kExample + "'");
  EXPECT_NE(r.output.find(line), std::string::npos) << r.output;
  const auto off = run_coldspray("check '" + kExample + "' --set metrics.verdict_extensions=0");
  EXPECT_EQ(off.status, 0) << off.output;
  EXPECT_EQ(off.output.find("the run goes on"), std::string::npos) << off.output;
}

TEST(Cli, CheckNamesFileLineAndKeyOfAnUnknownKey) {
  const auto r = run_coldspray("check '" + kData + "/cli/unknown-key.yaml'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unknown-key.yaml:6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("spacng"), std::string::npos) << r.output;
}

TEST(Cli, CheckNamesTheKeyOfAWrongDimension) {
  const auto r = run_coldspray("check '" + kData + "/cli/wrong-dimension.yaml'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("wrong-dimension.yaml:5:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("radius"), std::string::npos) << r.output;
}

TEST(Cli, SetOverrideErrorsNameTheOverride) {
  const auto r =
      run_coldspray("check '" + kExample + "' --set 'bodies.particle.velocity=[0, 0, -700 um]'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--set"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("velocity"), std::string::npos) << r.output;
}

TEST(Cli, SetOverrideOfAValidValueIsAccepted) {
  const auto r =
      run_coldspray("check '" + kExample + "' --set 'bodies.particle.velocity=[0, 0, -700 m/s]'");
  EXPECT_EQ(r.status, 0) << r.output;
}

TEST(Cli, RunWithABadCaseWritesNothing) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + kData + "/cli/unknown-key.yaml' --out result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_FALSE(fs::exists(fs::path(dir) / "result"));
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Cli, RunOfOverlappingBodiesIsBadInputAndWritesNothing) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + kData + "/cli/overlap.yaml' --out result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("bodies.particle.shape"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("overlaps body 'substrate'"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Cli, RunThatLosesABodyStopsWithStatus3AndKeepsALastSnapshot) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + kData + "/cli/escape.yaml' --out result --quiet", dir);
  EXPECT_EQ(r.status, 3) << r.output;
  // Its layers of 16 points leave one by one; the third takes 75 % of the block.
  EXPECT_NE(r.output.find("body 'block': 75 % of its mass has left the grid"), std::string::npos)
      << r.output;
  const fs::path out = fs::path(dir) / "result";
  EXPECT_TRUE(fs::exists(out / "snapshots.pvd"));
  EXPECT_TRUE(fs::exists(out / "case.resolved.yaml"));
  const std::string text = read_text(out / "summary.json");
  EXPECT_NE(text.find("\"status\": \"fault: body 'block'"), std::string::npos) << text;
}

TEST(Cli, RunWritesTheDocumentedResults) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                                   "/examples/verification/elastic-wave.yaml' --out result --quiet "
                                   "--set solver.end_time='0.5 ns'",
                               dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path out = fs::path(dir) / "result";
  for (const char* f :
       {"summary.json", "history.csv", "probes.csv", "snapshots.pvd", "case.resolved.yaml"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const Table probes = read_table((out / "probes.csv").string());
  EXPECT_EQ(probes.header.front(), "time");
  EXPECT_EQ(probes.header.at(1), "z10.velocity_z");
  // The resolved echo runs again to the same case.
  const auto again = run_coldspray("check '" + (out / "case.resolved.yaml").string() + "'", dir);
  EXPECT_EQ(again.status, 0) << again.output;
}

TEST(Cli, MaterialTestWritesTheDocumentedColumns) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "material-test --material cu-jc --mode uniaxial-strain --strain-rate '1e4 1/s' "
      "--final-strain -0.1 --steps 50 --out cu.csv",
      dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const Table csv = read_table((fs::path(dir) / "cu.csv").string());
  const std::vector<std::string> expected = {
      "time",          "strain",      "eqps",      "eqps_rate", "temperature", "melt_temperature",
      "shear_modulus", "flow_stress", "von_mises", "pressure",  "density"};
  EXPECT_EQ(csv.header, expected);
  ASSERT_EQ(csv.rows.size(), 51u);
  // 50 steps of -0.1/50 in log strain at 1e4 1/s: t = 1e-5 s, strain -0.1, rho = rho0 e^0.1.
  EXPECT_NEAR(csv.rows.back()[csv.column("time")], 1e-5, 1e-15);
  EXPECT_NEAR(csv.rows.back()[csv.column("strain")], -0.1, 1e-12);
  EXPECT_NEAR(csv.rows.back()[csv.column("density")], 8930.0 * std::exp(0.1), 1e-6);
}

// The acceptance point: al-ptw at eqps 0.5, plastic strain rate 1e7 1/s, 298 K,
// isothermal. At this rate PTW's power-law branches win in both tau_s and tau_y (eq 2.7a/b),
// so tau_s = tau_y = s0 (rate/(gamma xi_dot))^s1 and the flow stress is the saturation stress
// 2 tau_s mu(T) (eq 2.4 at beta = 0), whatever the strain. Hand value at rho = rho0, with the
// physical atomic mass M = 26.9815 u = 4.48039e-26 kg:
// mu(298 K) = 28.8 - 3.44/(e^(215/298) - 1) = 25.547 GPa (eq 2.6);
// xi_dot = 0.5 (4 pi 2700/(3 * 4.48039e-26))^(1/3) (25.547e9/2700)^(1/2) = 9.7201e12 1/s (2.8);
// r = rate/(gamma xi_dot) = 1e7/(2.04e-5 * 9.7201e12) = 0.050431;
// s0 r^s1 = 0.01489 * 0.050431^0.2034 = 0.0081101.
// Branches: Tm = 1220 K (SCG at rho0), erf(1.3 (298/1220) ln(1/0.050431)) = erf(0.94854)
// = 0.82022, so the thermal tau_s = 0.01489 - 0.012071 * 0.82022 = 0.0049891 is below s0 r^s1;
// y1 r^y2 = 0.0168 * 0.050431^0.2339 = 0.0083535 is above it, so the min of eq 2.7b is s0 r^s1
// too: tau_s = tau_y = 0.0081101 and sigma_y = 2 * 0.0081101 * 25.547e9 = 414.4 MPa.
TEST(Cli, MaterialTestAlPtwFlowStressAtTheAcceptancePoint) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "material-test --material al-ptw --mode uniaxial-stress --strain-rate '1e7 1/s' "
      "--final-strain -0.6 --isothermal --steps 1200 --out al.csv",
      dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const Table csv = read_table((fs::path(dir) / "al.csv").string());
  const auto eqps = csv.column("eqps"), rate = csv.column("eqps_rate");
  const auto flow = csv.column("flow_stress"), vm = csv.column("von_mises");
  const auto temperature = csv.column("temperature"), rho = csv.column("density");
  const auto& row = *std::find_if(csv.rows.begin(), csv.rows.end(),
                                  [&](const auto& v) { return v[eqps] >= 0.5; });
  EXPECT_NEAR(row[eqps], 0.5, 1e-3);
  // Plastic work raises the Mie-Gruneisen pressure, so the volume grows a little and the plastic
  // rate exceeds the imposed axial rate by about half a percent.
  EXPECT_NEAR(row[rate], 1e7, 1e7 * 1e-2);
  EXPECT_DOUBLE_EQ(row[temperature], 298.0);
  // Independent evaluation of the saturated branch at the row's own rate and density.
  const double mu = 28.8e9 - 3.44e9 / (std::exp(215.0 / 298.0) - 1.0);
  const double xi_dot = 0.5 * std::cbrt(4.0 * std::numbers::pi * row[rho] / (3.0 * 4.48039e-26)) *
                        std::sqrt(mu / row[rho]);
  const double r_hat = row[rate] / (2.04e-5 * xi_dot);
  const double power_law = 0.01489 * std::pow(r_hat, 0.2034);
  // The row is on the saturated branch: s0 r^s1 above the thermal tau_s (at the row's own Tm)
  // and below y1 r^y2.
  const double T_hat = 298.0 / row[csv.column("melt_temperature")];
  const double thermal =
      0.01489 - (0.01489 - 0.002819) * std::erf(1.3 * T_hat * std::log(1.0 / r_hat));
  EXPECT_GT(power_law, thermal);
  EXPECT_LT(power_law, 0.0168 * std::pow(r_hat, 0.2339));
  const double hand = 2.0 * power_law * mu;
  EXPECT_NEAR(row[flow], hand, 1e-6 * hand);
  EXPECT_NEAR(row[flow], 414.4e6, 1e6);
  EXPECT_NEAR(row[vm], row[flow], 1e-8 * row[flow]);  // on the yield surface
}

TEST(Cli, MaterialTestRejectsARateWithTheWrongUnit) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "material-test --material al-ptw --strain-rate '1e7 m/s' --final-strain -0.1 --out a.csv",
      dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--strain-rate"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Cli, MaterialTestRejectsAnUnknownMode) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "material-test --material al-ptw --mode twist --strain-rate 1e3 --final-strain -0.1 "
      "--out a.csv",
      dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("twist"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Cli, MaterialTestReadsACaseFileMaterial) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("material-test --material '" + kData +
                                   "/cli/soft-al.yaml:soft-al' --mode simple-shear "
                                   "--strain-rate 1e3 --final-strain 0.2 --out s.csv",
                               dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const Table csv = read_table((fs::path(dir) / "s.csv").string());
  // von Mises material, yield 50 MPa, no hardening: in shear the von Mises stress is the yield.
  EXPECT_NEAR(csv.rows.back()[csv.column("von_mises")], 50e6, 1e-6 * 50e6);
}

}  // namespace
}  // namespace coldspray::testing
