// A body's penetration (bodies/penetration.hpp) by hand: two bodies of a few points each, moved
// by known amounts, and which impact decides whether a pair may bond.
#include "bodies/penetration.hpp"

#include <gtest/gtest.h>

#include "bodies/bodies.hpp"

namespace coldspray::bodies {
namespace {

// A "particle" of three points 1 um apart along z (masses 1, 2, 1), moving down at 100 m/s, and
// a one-point "substrate" at rest below it.
Bodies falling_column() {
  Bodies s;
  s.points.resize(4);
  const double z[] = {1e-6, 2e-6, 3e-6, -1e-6};
  const double m[] = {1.0, 2.0, 1.0, 5.0};
  for (std::size_t p = 0; p < 4; ++p) {
    s.points.position[2][p] = z[p];
    s.points.mass[p] = m[p];
  }
  BodyRange particle;
  particle.name = "particle", particle.begin = 0, particle.end = 3;
  particle.spacing = 1e-6;
  particle.initial_velocity = {0.0, 0.0, -100.0};
  BodyRange substrate;
  substrate.name = "substrate", substrate.begin = 3, substrate.end = 4;
  substrate.spacing = 1e-6;
  s.bodies = {particle, substrate};
  s.contact_impulse.assign(4, {0.0, 0.0, 0.0});
  start_penetration(s);
  return s;
}

void move_particle(Bodies& s, double dz) {
  for (std::size_t p = 0; p < 3; ++p) s.points.position[2][p] += dz;
}

void step(Bodies& s, bool touching) {
  s.dt = 1e-9;
  s.time += s.dt;
  s.contact_impulse[1] = {0.0, 0.0, touching ? 1e-12 : 0.0};  // on the particle from the substrate
  s.contact_impulse[2] = {0.0, 0.0, touching ? -1e-12 : 0.0};
  track_penetration(s);
}

TEST(Penetration, SizeAndDirectionFromTheBodyAtTheStart) {
  const Bodies s = falling_column();
  const Penetration& p = s.bodies[0].penetration;
  EXPECT_DOUBLE_EQ(p.direction[2], -1.0);
  EXPECT_DOUBLE_EQ(p.size, 3e-6);                // 1 to 3 um, plus a spacing
  EXPECT_DOUBLE_EQ(p.last, -2e-6);               // the centroid z = 2 um, along -z
  EXPECT_EQ(s.bodies[1].penetration.size, 0.0);  // at rest: no penetration
}

TEST(Penetration, CountsTheCentroidsTravelFromTheFirstContactOverTheSize) {
  Bodies s = falling_column();
  move_particle(s, -0.5e-6);  // in flight: not counted
  step(s, false);
  EXPECT_LT(s.bodies[0].penetration.first_contact, 0.0);
  move_particle(s, -0.3e-6);  // the step it first touches: counted from the step's start
  step(s, true);
  EXPECT_DOUBLE_EQ(s.bodies[0].penetration.first_contact, 1e-9);
  EXPECT_DOUBLE_EQ(s.bodies[1].penetration.first_contact, 1e-9);  // the substrate touched too
  EXPECT_NEAR(s.bodies[0].penetration.largest, 0.1, 1e-12);       // 0.3 um of 3 um
  move_particle(s, -0.6e-6);
  step(s, true);
  EXPECT_NEAR(s.bodies[0].penetration.largest, 0.3, 1e-12);
  EXPECT_LT(s.bodies[0].penetration.peak, 0.0);  // still advancing
  move_particle(s, 0.2e-6);  // the rebound: the compression ended, the largest stays
  step(s, true);
  EXPECT_NEAR(s.bodies[0].penetration.largest, 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(s.bodies[0].penetration.peak, 4e-9);
}

Penetration impact(double first_contact, double largest, double peak) {
  Penetration p;
  p.size = 1.0;
  p.first_contact = first_contact;
  p.largest = largest;
  p.peak = peak;
  return p;
}

TEST(Penetration, APairIsActivatedOnceItsImpactPenetratesTheCriticalShare) {
  const Penetration substrate = impact(0.0, 0.0, -1.0);
  // Touching since the same step: the particle's impact decides, whichever comes first.
  EXPECT_FALSE(pair_activated(impact(0.0, 0.39, -1.0), substrate, 0.4));
  EXPECT_FALSE(pair_activated(substrate, impact(0.0, 0.39, 1e-8), 0.4));
  EXPECT_TRUE(pair_activated(impact(0.0, 0.4, -1.0), substrate, 0.4));
  EXPECT_TRUE(pair_activated(substrate, impact(0.0, 0.41, 1e-8), 0.4));
  EXPECT_TRUE(pair_activated(impact(0.0, 0.0, -1.0), substrate, 0.0));  // the thesis' model
  // A later arrival's impact decides, not the earlier body's.
  const Penetration deposited = impact(0.0, 0.5, 1e-8);
  EXPECT_FALSE(pair_activated(deposited, impact(5e-8, 0.3, 7e-8), 0.4));
  EXPECT_TRUE(pair_activated(impact(5e-8, 0.45, 7e-8), deposited, 0.4));
  EXPECT_FALSE(pair_activated(deposited, impact(-1.0, 0.0, -1.0), 0.4));  // not touched yet
}

}  // namespace
}  // namespace coldspray::bodies
