// peridynamics.subcycling (pd/stepper.hpp, docs/pd.md "Subcycling"): a small elastic sphere at
// 0.5 um spacing hits a larger one at 1 um (tests/data/cli/pd-two-spacings.yaml, to 14 ns). Its
// own stable step is half the large one's, so it takes two steps per step of the large sphere:
// half the steps of the single-rate run. The contact's impulses on the large sphere are those the
// small one's kicks gave in return, so momentum is conserved to round-off; the rebound is the
// single-rate run's to 0.1 %.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "run_command.hpp"
#include "summary_json.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

double momentum_z(const nlohmann::json& s) {
  double p = 0.0;
  for (const char* body : {"small", "large"})
    p += s["bodies"][body]["mass"].get<double>() * s["bodies"][body]["velocity"][2].get<double>();
  return p;
}

TEST(Subcycling, TheFineBodyTakesTwoStepsAndMomentumIsKept) {
  const fs::path dir = make_temp_dir();
  const std::string run =
      "run '" + std::string(COLDSPRAY_TEST_DATA) + "/cli/pd-two-spacings.yaml' --quiet --out ";
  const auto single = run_coldspray(run + "single", dir);
  ASSERT_EQ(single.status, 0) << single.output;
  const auto sub = run_coldspray(run + "sub --set peridynamics.subcycling=true", dir);
  ASSERT_EQ(sub.status, 0) << sub.output;
  const nlohmann::json s = read_summary(dir / "single"), c = read_summary(dir / "sub");

  // 145 steps single-rate, 72 subcycled (measured): the large sphere's step, twice the small's.
  EXPECT_LT(c["steps"].get<double>(), 0.55 * s["steps"].get<double>());
  const double p0 = -100.0 * c["bodies"]["small"]["mass"].get<double>();
  EXPECT_NEAR(momentum_z(c), p0, 1e-12 * std::abs(p0));
  // After the collision (about 7 to 11.5 ns) the small sphere leaves at 87.7 m/s, the large one
  // at -11.9 m/s (single-rate 87.72 and -11.908, subcycled 87.65 and -11.903, measured).
  for (const char* body : {"small", "large"}) {
    const double v_single = s["bodies"][body]["velocity"][2].get<double>();
    EXPECT_NEAR(c["bodies"][body]["velocity"][2].get<double>(), v_single,
                1e-3 * std::abs(v_single) + 0.02)
        << body;
  }
  EXPECT_GT(s["bodies"]["small"]["velocity"][2].get<double>(), 85.0);
  // The budget closes as well as single-rate: -1.0e-4 against -2.7e-4 (measured).
  EXPECT_LT(std::abs(c["energy"]["relative_error"].get<double>()), 1e-3);
}

}  // namespace
}  // namespace coldspray::testing
