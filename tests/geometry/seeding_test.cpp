// Lattice seeding: volumes against the shapes' exact volumes, surface flags against counting.
#include "geometry/seeding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace coldspray::geometry {
namespace {

using std::numbers::pi;

double total(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }
long count_surface(const std::vector<std::uint8_t>& outside) {
  return std::count_if(outside.begin(), outside.end(), [](std::uint8_t o) { return o != 0; });
}

TEST(Seeding, BoxHasExactCountVolumeAndSurfaceShell) {
  // A 2 x 1 x 1 um box at 0.1 um spacing from a lattice origin on its corner: 20 x 10 x 10 sites,
  // the outer shell on the surface: 2000 - 18 * 8 * 8.
  const Box box{Vec3(0, 0, 0), Vec3(2e-6, 1e-6, 1e-6)};
  const SeededPoints p = seed(box, Lattice{Vec3::Zero(), 0.1e-6, false});
  ASSERT_EQ(p.position.size(), 2000u);
  EXPECT_NEAR(total(p.volume), 2e-18, 1e-30);
  EXPECT_EQ(count_surface(p.outside), 2000 - 18 * 8 * 8);
}

TEST(Seeding, SphereVolumeConvergesToTheExactVolume) {
  // The lattice volume of a sphere of radius R = 20 spacings is within 1 % of 4/3 pi R^3.
  const double R = 7e-6;
  const Sphere sphere{Vec3(0, 0, R), R};
  const SeededPoints p = seed(sphere, Lattice{Vec3::Zero(), R / 20.0, false});
  const double exact = 4.0 / 3.0 * pi * R * R * R;
  EXPECT_NEAR(total(p.volume), exact, 0.01 * exact);
  for (std::size_t i = 0; i < p.position.size(); ++i)
    EXPECT_LE((p.position[i] - sphere.center).norm(), R);
}

TEST(Seeding, AxisymmetricCylinderRingsAddUpExactly) {
  // Rings at r = (i + 1/2) s, i < N, hold 2 pi s^2 (i + 1/2) s each per layer: the sum over i is
  // pi (N s)^2 s, so a cylinder R = N s, h = M s is filled exactly.
  const double s = 0.25e-6;
  const Cylinder cyl{Vec3(0, 0, -10e-6), 15e-6, 10e-6};
  const SeededPoints p = seed(cyl, Lattice{Vec3::Zero(), s, true});
  ASSERT_EQ(p.position.size(), 60u * 40u);
  EXPECT_NEAR(total(p.volume), pi * 15e-6 * 15e-6 * 10e-6, 1e-12 * pi * 15e-6 * 15e-6 * 10e-6);
  for (const Vec3& x : p.position) {
    EXPECT_GT(x.x(), 0.0);
    EXPECT_EQ(x.y(), 0.0);
  }
  // Surface: the outer column, top and bottom rows; the axis is not a surface.
  EXPECT_EQ(count_surface(p.outside), 40 + 2 * 59);
  // The bottom row has its -z neighbour outside; the outer column its +r neighbour.
  long bottom = 0, side = 0;
  for (std::uint8_t o : p.outside) {
    bottom += (o & kMinusZ) != 0;
    side += (o & kPlusX) != 0;
    EXPECT_EQ(o & kMinusX, 0);  // the axis is not a surface
  }
  EXPECT_EQ(bottom, 60);
  EXPECT_EQ(side, 40);
}

TEST(Seeding, AxisymmetricSphereMatchesThe3DVolume) {
  const double R = 7e-6;
  const Sphere sphere{Vec3(0, 0, R), R};
  const SeededPoints p = seed(sphere, Lattice{Vec3::Zero(), R / 40.0, true});
  const double exact = 4.0 / 3.0 * pi * R * R * R;
  EXPECT_NEAR(total(p.volume), exact, 0.005 * exact);
}

}  // namespace
}  // namespace coldspray::geometry
