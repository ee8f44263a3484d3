// `coldspray bulk-fracture`: contact model 2's bulk-fracture test and fit, written where asked,
// against hand values for cu-jc at 1.2 um (docs/pd.md, "Contact model 2").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "run_command.hpp"
#include "table.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

TEST(BulkFractureCommand, WritesTheCurveAndTheFitForCopper) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("bulk-fracture --material cu-jc --spacing 1.2um --out fit", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r, "s_c 0.0020896")) << r.output;
  std::ifstream in(fs::path(dir) / "fit" / "fit.json");
  const nlohmann::json fit = nlohmann::json::parse(in);
  // G_c = 2 x 1.825 J/m^2; delta = 3.6 um; c = 18 K / (pi delta^4) = 4.4005e33 N/m^6; eq 23:
  // s_c = sqrt(5 G_c / (9 K delta)) = 2.0896e-3.
  EXPECT_NEAR(fit["fracture_energy"].get<double>(), 3.65, 1e-12);
  const double c = 18.0 * 129e9 / (std::numbers::pi * std::pow(3.6e-6, 4));
  EXPECT_NEAR(fit["micromodulus"].get<double>() / c, 1.0, 1e-12);
  EXPECT_NEAR(fit["critical_stretch"].get<double>(), 2.0896e-3, 1e-7);
  // The bulk peaks where its steepest bonds break, at s_c; the fit keeps the bulk's work.
  EXPECT_NEAR(fit["yield_stretch"].get<double>() / fit["critical_stretch"].get<double>(), 1.0,
              2e-3);
  EXPECT_NEAR(fit["work_per_micromodulus_fitted"].get<double>() /
                  fit["work_per_micromodulus_bulk"].get<double>(),
              1.0, 1e-12);
  const Table curve = read_table((fs::path(dir) / "fit" / "bulk_fracture.csv").string());
  ASSERT_GT(curve.rows.size(), 9000u);  // to the last bond's break at 9 s_c, 1000 per s_c
  // Below s_c both curves are the bond's linear branch, c s (written to 9 digits).
  const auto& row = curve.rows[500];
  EXPECT_NEAR(row[curve.column("bulk_force_density")] / (c * row[curve.column("stretch")]), 1.0,
              1e-6);
  EXPECT_NEAR(row[curve.column("fitted_force_density")] / (c * row[curve.column("stretch")]), 1.0,
              1e-8);
  EXPECT_EQ(curve.rows.back()[curve.column("bulk_force_density")], 0.0);
}

TEST(BulkFractureCommand, RefusesAFractureEnergyThatIsNotPositive) {
  const std::string dir = make_temp_dir();
  const auto r =
      run_coldspray("bulk-fracture --material cu-jc --fracture-energy 0J/m^2 --out fit", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "--fracture-energy")) << r.output;
  EXPECT_FALSE(fs::exists(fs::path(dir) / "fit"));
}

}  // namespace
}  // namespace coldspray::testing
