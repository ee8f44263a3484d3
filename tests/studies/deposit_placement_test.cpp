// The particles of `coldspray deposit` (studies/deposit_placement.hpp): reproducible from the
// seed, never overlapping, arriving in order at the heights their speeds and times give, sizes
// and speeds as the distribution and the size law say.
#include "studies/deposit_placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "studies/deposit_room.hpp"

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

// The sizes the deposit is sized by before placement are those placed (in another order: the
// placement sorts them by arrival).
TEST(DepositPlacement, DrawDiametersGivesThePlacedSizes) {
  const DepositPlan plan = ten_particles(5);
  std::vector<double> drawn = draw_diameters(plan), placed;
  for (const PlacedParticle& p : place_particles(plan).particles) placed.push_back(p.diameter);
  std::sort(drawn.begin(), drawn.end());
  std::sort(placed.begin(), placed.end());
  EXPECT_EQ(drawn, placed);
}

// The room is a bound no placement beats: every plan placed in full fits it (50 seeds), and the
// ten 14 um particles that cannot all lie on a 20 um patch at once do not: their spheres grown by
// half the clearance, 8.175 um, fill 22 884 um^3 against (20 + 16.35)^2 x 16.35 = 21 600 um^3.
TEST(DepositPlacement, TheRoomHoldsEveryPlacementThatSucceeds) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    DepositPlan plan = ten_particles(seed);
    plan.patch = {40e-6, 40e-6};
    ASSERT_EQ(place_particles(plan).unplaced, -1);
    EXPECT_TRUE(deposit_room(plan, draw_diameters(plan)).fits()) << seed;
  }
  DepositPlan flat = ten_particles(1);
  flat.diameter = {SizeDistribution::Kind::Fixed, 14e-6, 0.0};
  flat.patch = {20e-6, 20e-6};
  flat.arrival_window = 0.0;
  const DepositRoom room = deposit_room(flat, draw_diameters(flat));
  EXPECT_NEAR(room.needed, 10 * 4.0 / 3.0 * std::numbers::pi * std::pow(8.175e-6, 3), 1e-21);
  EXPECT_NEAR(room.room, std::pow(36.35e-6, 2) * 16.35e-6, 1e-21);
  EXPECT_FALSE(room.fits());
  EXPECT_EQ(room.most, 9);
}

}  // namespace
}  // namespace coldspray::studies
