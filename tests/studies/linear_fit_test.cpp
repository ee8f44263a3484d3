// Least-squares line: exact data, and the thesis' predicted critical velocities (Table 5.4)
// against a hand calculation.
#include "studies/linear_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace coldspray::studies {
namespace {

TEST(StudiesLinearFit, ExactDataGiveTheCoefficients) {
  const std::vector<double> x = {14.0, 18.0, 22.0, 26.0, 30.0, 11.5};
  std::vector<double> y;
  for (double v : x) y.push_back(879.65 - 3.975 * v);
  const LinearFit f = fit_line(x, y);
  EXPECT_NEAR(f.a, 879.65, 1e-12 * 879.65);
  EXPECT_NEAR(f.b, -3.975, 1e-12 * 3.975);
  EXPECT_NEAR(f.r_squared, 1.0, 1e-14);
  EXPECT_NEAR(f.se_a, 0.0, 1e-10);
  EXPECT_NEAR(f.se_b, 0.0, 1e-11);
  EXPECT_EQ(f.n, 6u);
  EXPECT_NEAR(f(20.0), 800.15, 1e-12 * 800.0);

  const LinearFit g =
      fit_line(std::vector<double>{0.0, 1.0, 2.0}, std::vector<double>{0.5, 2.0, 3.5});
  EXPECT_NEAR(g.a, 0.5, 1e-15);
  EXPECT_NEAR(g.b, 1.5, 1e-15);
}

// d = 14..30 um, vcrit = 824, 809, 791, 776, 761 m/s. By hand: mean d 22, mean v 792.2,
// Sxx = 160, Sxy = -636, b = -3.975, a = 879.65; residuals 0, 0.9, -1.2, -0.3, 0.6, SS_res 2.7,
// SS_tot 2530.8; s^2 = 0.9, se_b = sqrt(0.9 / 160) = 0.075, se_a = sqrt(0.9 (1/5 + 484/160)).
TEST(StudiesLinearFit, ThesisCriticalVelocitiesMatchAHandCalculation) {
  const std::vector<double> d = {14.0, 18.0, 22.0, 26.0, 30.0};
  const std::vector<double> v = {824.0, 809.0, 791.0, 776.0, 761.0};
  const LinearFit f = fit_line(d, v);
  EXPECT_NEAR(f.b, -3.975, 1e-12);
  EXPECT_NEAR(f.a, 879.65, 1e-11);
  EXPECT_NEAR(f.r_squared, 1.0 - 2.7 / 2530.8, 1e-12);
  EXPECT_NEAR(f.residual_std, std::sqrt(0.9), 1e-12);
  EXPECT_NEAR(f.se_b, 0.075, 1e-12);
  EXPECT_NEAR(f.se_a, std::sqrt(0.9 * (0.2 + 484.0 / 160.0)), 1e-11);
}

TEST(StudiesLinearFit, DegenerateCases) {
  const LinearFit two = fit_line(std::vector<double>{1.0, 2.0}, std::vector<double>{1.0, 3.0});
  EXPECT_NEAR(two.b, 2.0, 1e-15);
  EXPECT_TRUE(std::isnan(two.se_a));
  EXPECT_TRUE(std::isnan(two.se_b));
  const LinearFit flat =
      fit_line(std::vector<double>{1.0, 2.0, 3.0}, std::vector<double>{4.0, 4.0, 4.0});
  EXPECT_EQ(flat.b, 0.0);
  EXPECT_TRUE(std::isnan(flat.r_squared));
  EXPECT_THROW(fit_line(std::vector<double>{1.0}, std::vector<double>{1.0}), std::invalid_argument);
  EXPECT_THROW(fit_line(std::vector<double>{1.0, 1.0}, std::vector<double>{1.0, 2.0}),
               std::invalid_argument);
  EXPECT_THROW(fit_line(std::vector<double>{1.0, 2.0}, std::vector<double>{1.0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace coldspray::studies
