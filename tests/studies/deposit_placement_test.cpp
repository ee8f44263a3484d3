// The particles of `coldspray deposit` (studies/deposit_placement.hpp): reproducible from the
// seed, never overlapping, arriving in order at the heights their speeds and times give, sizes
// and speeds as the distribution and the size law say.
#include "studies/deposit_placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace coldspray::studies {
namespace {

DepositPlan ten_particles(std::uint64_t seed) {
  DepositPlan plan;
  plan.count = 10;
  plan.diameter = {SizeDistribution::Kind::Normal, 14e-6, 1.5e-6};
  plan.speed = 810.0;
  plan.speed_diameter = 14e-6;
  plan.patch = {30e-6, 30e-6};
  plan.arrival_window = 80e-9;
  plan.clearance = 2.35e-6;
  plan.seed = seed;
  return plan;
}

double distance(const PlacedParticle& a, const PlacedParticle& b) {
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) d2 += (a.centre[k] - b.centre[k]) * (a.centre[k] - b.centre[k]);
  return std::sqrt(d2);
}

TEST(DepositPlacement, TheSameSeedGivesTheSameParticlesAndAnotherOtherOnes) {
  const Placement a = place_particles(ten_particles(7));
  const Placement b = place_particles(ten_particles(7));
  const Placement c = place_particles(ten_particles(8));
  ASSERT_EQ(a.unplaced, -1);
  ASSERT_EQ(a.particles.size(), 10u);
  ASSERT_EQ(c.particles.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(a.particles[i].diameter, b.particles[i].diameter);
    EXPECT_EQ(a.particles[i].arrival, b.particles[i].arrival);
    EXPECT_EQ(a.particles[i].centre, b.particles[i].centre);
  }
  EXPECT_NE(a.particles[3].centre, c.particles[3].centre);
  EXPECT_NE(a.particles[3].diameter, c.particles[3].diameter);
}

TEST(DepositPlacement, NoTwoParticlesComeCloserThanTheClearance) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    DepositPlan plan = ten_particles(seed);
    plan.patch = {40e-6, 40e-6};  // room for ten at any seed: the test is of the gaps
    const Placement placed = place_particles(plan);
    ASSERT_EQ(placed.unplaced, -1) << seed;
    const auto& p = placed.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j)
        EXPECT_GE(distance(p[i], p[j]), 0.5 * (p[i].diameter + p[j].diameter) + plan.clearance)
            << "seed " << seed << ", particles " << i << " and " << j;
  }
}

// The first arrives at t = 0 touching z = 0; the others in order within the window, each with its
// bottom speed x arrival above z = 0 and its centre over the patch.
TEST(DepositPlacement, ParticlesStartWhereTheirArrivalTimesPutThem) {
  const DepositPlan plan = ten_particles(3);
  const Placement placed = place_particles(plan);
  const auto& p = placed.particles;
  EXPECT_EQ(p.front().arrival, 0.0);
  EXPECT_DOUBLE_EQ(p.front().centre[2], 0.5 * p.front().diameter);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i > 0) {
      EXPECT_GE(p[i].arrival, p[i - 1].arrival);
    }
    EXPECT_LE(p[i].arrival, plan.arrival_window);
    EXPECT_NEAR(p[i].centre[2] - 0.5 * p[i].diameter, p[i].speed * p[i].arrival, 1e-18);
    EXPECT_LE(std::abs(p[i].centre[0]), 0.5 * plan.patch[0]);
    EXPECT_LE(std::abs(p[i].centre[1]), 0.5 * plan.patch[1]);
  }
}

// Many draws on a wide patch: the normal sizes' mean and deviation, all within three deviations;
// the log-normal sizes' logarithms likewise about the median's; and the speed law by hand.
TEST(DepositPlacement, SizesFollowTheDistributionAndSpeedsTheSizeLaw) {
  DepositPlan plan = ten_particles(11);
  plan.count = 4000;
  plan.patch = {1.0, 1.0};  // a metre: room for all
  plan.speed_exponent = -0.5;
  const Placement normal = place_particles(plan);
  ASSERT_EQ(normal.unplaced, -1);
  std::vector<double> d;
  for (const auto& p : normal.particles) d.push_back(p.diameter);
  const double mean = std::accumulate(d.begin(), d.end(), 0.0) / d.size();
  double var = 0.0;
  for (double x : d) var += (x - mean) * (x - mean);
  const double deviation = std::sqrt(var / (d.size() - 1));
  // Standard errors: 1.5/sqrt(4000) = 0.024 um on the mean; the truncation at 3 deviations
  // narrows the deviation by 1.4 %.
  EXPECT_NEAR(mean, 14e-6, 0.1e-6);
  EXPECT_NEAR(deviation, 1.5e-6 * 0.986, 0.05e-6);
  EXPECT_GE(*std::min_element(d.begin(), d.end()), 14e-6 - 4.5e-6);
  EXPECT_LE(*std::max_element(d.begin(), d.end()), 14e-6 + 4.5e-6);
  const PlacedParticle& any = normal.particles[17];
  EXPECT_DOUBLE_EQ(any.speed, 810.0 * std::pow(any.diameter / 14e-6, -0.5));

  plan.diameter = {SizeDistribution::Kind::LogNormal, 20e-6, 1.3};
  const Placement log_normal = place_particles(plan);
  double log_mean = 0.0, log_var = 0.0;
  for (const auto& p : log_normal.particles) log_mean += std::log(p.diameter);
  log_mean /= plan.count;
  for (const auto& p : log_normal.particles)
    log_var += (std::log(p.diameter) - log_mean) * (std::log(p.diameter) - log_mean);
  EXPECT_NEAR(std::exp(log_mean), 20e-6, 0.2e-6);
  EXPECT_NEAR(std::exp(std::sqrt(log_var / (plan.count - 1))), 1.3, 0.01);
  EXPECT_DOUBLE_EQ(plan.diameter.smallest(), 20e-6 / std::pow(1.3, 3));
  EXPECT_DOUBLE_EQ(plan.diameter.largest(), 20e-6 * std::pow(1.3, 3));
}

// Ten 14 um particles arriving at once on a 20 um patch: their centres must lie 16.35 um apart,
// and at most four such points fit in a 20 um square (five need a spacing of at most
// 20 / sqrt 2 = 14.1 um, the corners and the centre), so placement stops by the fifth particle.
TEST(DepositPlacement, ReportsTheFirstParticleWithoutAPlace) {
  DepositPlan plan = ten_particles(1);
  plan.diameter = {SizeDistribution::Kind::Fixed, 14e-6, 0.0};
  plan.patch = {20e-6, 20e-6};
  plan.arrival_window = 0.0;
  const Placement placed = place_particles(plan);
  ASSERT_GE(placed.unplaced, 1);
  EXPECT_LE(placed.unplaced, 4);
  EXPECT_EQ(placed.particles.size(), static_cast<std::size_t>(placed.unplaced));
}

}  // namespace
}  // namespace coldspray::studies
