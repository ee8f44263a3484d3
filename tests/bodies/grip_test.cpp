// The pull-off test's grip (bodies/grip.hpp), by hand on a splat of a few points: a flat base at
// z = 1 um with a rim folded up to z = 3 um at its edges, a drop it shed high above, and a
// substrate below; which points the grip takes, at what velocity, and when it refuses.
#include "bodies/grip.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "input_error.hpp"
#include "units.hpp"

namespace coldspray::bodies {
namespace {

using coldspray::testing::contains;
using coldspray::testing::input_error;
using coldspray::testing::um;

struct Site {
  double x, z;  // um
};

// Body 0, "particle" (spacing 1 um, initial diameter `diameter`), at `particle`; body 1,
// "substrate", at `substrate`; every point of mass 1 on y = 0, moving at 5 m/s along x, with a
// displacement left over from its last step.
Bodies splat(const std::vector<Site>& particle, const std::vector<Site>& substrate,
             double diameter = 2.2 * um) {
  Bodies s;
  const std::size_t n = particle.size() + substrate.size();
  s.points.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const bool first = p < particle.size();
    const Site& x = first ? particle[p] : substrate[p - particle.size()];
    s.points.position[0][p] = x.x * um;
    s.points.position[2][p] = x.z * um;
    s.points.mass[p] = 1.0;
    s.points.body[p] = first ? 0 : 1;
    s.points.velocity[0][p] = 5.0;
    s.points.displacement[2][p] = 1e-9;
  }
  BodyRange a;
  a.name = "particle", a.begin = 0, a.end = particle.size(), a.spacing = um;
  a.initial_diameter = diameter;
  BodyRange b;
  b.name = "substrate", b.begin = particle.size(), b.end = n, b.spacing = um;
  s.bodies = {a, b};
  return s;
}

// The splat's base (indices 0-4), its rim (5-8: x = -2 and 2 um at z = 2 and 3 um) and a drop
// 17 um above the rim, farther than the piece's link of 3 spacings (index 9).
const std::vector<Site> kSplat = {{-2, 1}, {-1, 1}, {0, 1}, {1, 1}, {2, 1},
                                  {-2, 2}, {-2, 3}, {2, 2}, {2, 3}, {0, 20}};
const std::vector<Site> kSubstrate = {{-2, 0}, {-1, 0}, {0, 0}, {1, 0}, {2, 0}};

case_file::Grip grip_up(double fraction) {
  case_file::Grip g;
  g.body = "particle";
  g.fraction = fraction;
  g.velocity = {0.0, 0.0, 10.0};
  return g;
}

std::vector<std::size_t> gripped(const Bodies& s) {
  std::vector<std::size_t> out;
  for (std::size_t p = 0; p < s.points.size(); ++p)
    if (s.gripped[p]) out.push_back(p);
  return out;
}

TEST(Grip, ItsVelocityRisesAlongAHalfCosineOverTheRamp) {
  Bodies s;
  case_file::Grip g = grip_up(0.3);
  g.ramp = 4e-9;
  prepare_grip(s, g);
  EXPECT_NEAR(grip_velocity_at(s, 0.0)[2], 0.0, 1e-15);
  EXPECT_NEAR(grip_velocity_at(s, 1e-9)[2], 1.46446609, 1e-8);  // 10 (1 - cos(pi/4)) / 2
  EXPECT_NEAR(grip_velocity_at(s, 2e-9)[2], 5.0, 1e-12);
  EXPECT_EQ(grip_velocity_at(s, 4e-9)[2], 10.0);
  EXPECT_EQ(grip_velocity_at(s, 9e-9)[2], 10.0);
  EXPECT_EQ(grip_velocity_at(s, 1e-9)[0], 0.0);
  s.grip_ramp = 0.0;  // no ramp: all of it from the start
  EXPECT_EQ(grip_velocity_at(s, 0.0)[2], 10.0);
}

TEST(Grip, TakesTheLastShareOfTheSplatAlongItsSideNotTheDropItShed) {
  Bodies s = splat(kSplat, kSubstrate);
  prepare_grip(s, grip_up(0.3));
  s.time = 2e-9, s.grip_ramp = 4e-9;
  take_grip(s, grip_up(0.3));
  // The splat spans z = 1-3 um; its last 30 % starts at 2.4 um: the rim's top points. The drop
  // at 20 um is no part of the splat.
  EXPECT_EQ(gripped(s), (std::vector<std::size_t>{6, 8}));
  for (std::size_t p = 0; p < s.points.size(); ++p) {
    const bool held = p == 6 || p == 8;
    EXPECT_EQ(s.points.velocity[0][p], 0.0) << "every point starts at rest";
    EXPECT_NEAR(s.points.velocity[2][p], held ? 5.0 : 0.0, 1e-12) << "half way up the ramp";
    EXPECT_EQ(s.points.displacement[2][p], 0.0);
  }
}

TEST(Grip, TheSideSetsTheDirectionOfTheShareNotTheVelocity) {
  Bodies s = splat(kSplat, kSubstrate);
  case_file::Grip g = grip_up(0.3);
  g.side = {1.0, 0.0, 0.0};  // x spans -2 to 2 um: from 0.8 um on
  prepare_grip(s, g);
  take_grip(s, g);
  EXPECT_EQ(gripped(s), (std::vector<std::size_t>{3, 4, 7, 8}));
  EXPECT_EQ(s.points.velocity[2][3], 10.0);
}

TEST(Grip, WhereAnotherBodyLiesAmongTheGrippedPointsOnlyTheCoreIsTaken) {
  // A lip of the crater at (0, 3 um), between the rim's tops: within the rim's box. The core is
  // the splat within the initial radius, 1.1 um, of the axis x = 0: the base's middle three.
  std::vector<Site> substrate = kSubstrate;
  substrate.push_back({0, 3});
  Bodies s = splat(kSplat, substrate);
  prepare_grip(s, grip_up(0.3));
  take_grip(s, grip_up(0.3));
  EXPECT_EQ(gripped(s), (std::vector<std::size_t>{1, 2, 3}));
}

TEST(Grip, ABodyAmongTheCoresPointsIsAnInputError) {
  std::vector<Site> substrate = kSubstrate;
  substrate.push_back({0, 3});
  substrate.push_back({0.5, 1});  // within the core's box, x -1 to 1 um at z = 1 um
  Bodies s = splat(kSplat, substrate);
  prepare_grip(s, grip_up(0.3));
  const InputError e = input_error([&] { take_grip(s, grip_up(0.3)); });
  EXPECT_EQ(e.key(), "grip.fraction");
  EXPECT_TRUE(contains(e.message(),
                       "the grip of 'particle' would take in points of 'substrate' (one "
                       "at [0.5, 0, 1] um"));
}

TEST(Grip, ACoreWithoutPointsIsAnInputError) {
  // No point of the splat within 0.5 um of its axis (x = 0): the base without its middle.
  const std::vector<Site> ring = {{-2, 1}, {-1, 1}, {1, 1}, {2, 1}, {-2, 3}, {2, 3}};
  std::vector<Site> substrate = kSubstrate;
  substrate.push_back({0, 3});
  Bodies s = splat(ring, substrate, 1 * um);
  prepare_grip(s, grip_up(0.3));
  const InputError e = input_error([&] { take_grip(s, grip_up(0.3)); });
  EXPECT_EQ(e.key(), "grip.fraction");
  EXPECT_TRUE(contains(e.message(), "the grip of 'particle' takes none of its points"));
}

}  // namespace
}  // namespace coldspray::bodies
