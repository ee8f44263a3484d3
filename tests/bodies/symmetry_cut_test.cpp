// Cutting seeded bodies at symmetry planes (bodies::cut_at_planes), by hand: which points stay,
// where a body remembers that it was cut, and what that does to the whole body's measures (its
// initial diameter, bodies/seed_bodies.hpp, and its axis, bodies/body_axis.hpp).
#include <gtest/gtest.h>

#include "bodies/body_axis.hpp"
#include "bodies/seed_bodies.hpp"
#include "core/error.hpp"
#include "elastic_case.hpp"
#include "input_error.hpp"
#include "units.hpp"

namespace coldspray::bodies {
namespace {

using coldspray::testing::contains;
using coldspray::testing::input_error;
using testing::box;
using testing::elastic_case;
using testing::kPointMass;

using coldspray::testing::um;

// A 2 x 2 x 1 um box centred on the z axis: 4 x 4 x 2 points at x, y = +-0.25, +-0.75 um.
case_file::Case centred() {
  return elastic_case(box("block", "[-1 um, -1 um, 0]", "[1 um, 1 um, 1 um]"));
}

const std::vector<CutPlane> kQuarter = {{0, 0.0, true}, {1, 0.0, true}};

TEST(SymmetryCut, AQuarterModelKeepsTheQuarterAndRemembersBothPlanes) {
  const case_file::Case c = centred();
  std::vector<SeededBody> seeded = seed_bodies(c);
  ASSERT_EQ(seeded[0].points.position.size(), 32u);
  cut_at_planes(c, kQuarter, "the test's planes", seeded);
  const SeededBody& q = seeded[0];
  ASSERT_EQ(q.points.position.size(), 8u);  // x, y in {0.25, 0.75} um, z in {0.25, 0.75} um
  for (const case_file::Vec3& x : q.points.position) {
    EXPECT_GT(x[0], 0.0);
    EXPECT_GT(x[1], 0.0);
  }
  ASSERT_TRUE(q.mirror_plane[0] && q.mirror_plane[1]);
  EXPECT_EQ(*q.mirror_plane[0], 0.0);
  EXPECT_EQ(*q.mirror_plane[1], 0.0);
  // Bounded again: the quarter's cubes span [0, 1] um on every axis.
  EXPECT_NEAR(q.min.norm(), 0.0, 1e-18);
  EXPECT_NEAR((q.max - case_file::Vec3(um, um, um)).norm(), 0.0, 1e-18);

  Bodies s;
  lay_out_bodies(c, seeded, s);
  ASSERT_EQ(s.points.size(), 8u);
  for (std::size_t p = 0; p < 8; ++p) EXPECT_NEAR(s.points.mass[p], kPointMass, 1e-30);
  // The whole body's diameter, not the quarter's: 2 x 0.75 um + a spacing.
  EXPECT_NEAR(s.bodies[0].initial_diameter, 2 * um, 1e-18);
  ASSERT_TRUE(s.bodies[0].mirror_plane[0] && s.bodies[0].mirror_plane[1]);
  // Its axis lies on both planes (the quarter's own centroid is at x = y = 0.5 um), at the
  // centroid's height.
  const Eigen::Vector3d axis = axis_point(s.points, s.bodies[0]);
  EXPECT_EQ(axis[0], 0.0);
  EXPECT_EQ(axis[1], 0.0);
  EXPECT_NEAR(axis[2], 0.5 * um, 1e-18);
}

TEST(SymmetryCut, ABodyThePlanesDoNotCutKeepsAllItsPointsAndNoMirror) {
  const case_file::Case c = elastic_case(box("aside", "[1 um, 1 um, 0]", "[2 um, 2 um, 1 um]"));
  std::vector<SeededBody> seeded = seed_bodies(c);
  cut_at_planes(c, kQuarter, "the test's planes", seeded);
  EXPECT_EQ(seeded[0].points.position.size(), 8u);
  EXPECT_FALSE(seeded[0].mirror_plane[0]);
  EXPECT_FALSE(seeded[0].mirror_plane[1]);
  Bodies s;
  lay_out_bodies(c, seeded, s);
  EXPECT_NEAR(s.bodies[0].initial_diameter, 1 * um, 1e-18);  // its own extent: 0.5 um + a spacing
  EXPECT_NEAR(axis_point(s.points, s.bodies[0])[0], 1.5 * um, 1e-18);
}

TEST(SymmetryCut, APlaneNormalToZCutsButIsNoMirror) {
  // The bodies' areas and diameters double only across x and y planes.
  const case_file::Case c = centred();
  std::vector<SeededBody> seeded = seed_bodies(c);
  cut_at_planes(c, {{2, 0.5 * um, true}}, "the test's planes", seeded);
  EXPECT_EQ(seeded[0].points.position.size(), 16u);  // the upper layer, z = 0.75 um
  for (const case_file::Vec3& x : seeded[0].points.position) EXPECT_GT(x[2], 0.5 * um);
  EXPECT_FALSE(seeded[0].mirror_plane[0]);
  EXPECT_FALSE(seeded[0].mirror_plane[1]);
}

TEST(SymmetryCut, KeepBelowKeepsTheOtherSide) {
  const case_file::Case c = centred();
  std::vector<SeededBody> seeded = seed_bodies(c);
  cut_at_planes(c, {{0, -0.5 * um, false}}, "the test's planes", seeded);
  ASSERT_EQ(seeded[0].points.position.size(), 8u);  // the column at x = -0.75 um
  for (const case_file::Vec3& x : seeded[0].points.position) EXPECT_NEAR(x[0], -0.75 * um, 1e-18);
  ASSERT_TRUE(seeded[0].mirror_plane[0]);
  EXPECT_EQ(*seeded[0].mirror_plane[0], -0.5 * um);
  Bodies s;
  lay_out_bodies(c, seeded, s);
  // Mirrored at x = -0.5 um: the points at -0.75 and their images at -0.25 um, 1 um across.
  EXPECT_NEAR(s.bodies[0].initial_diameter, 1 * um, 1e-18);
}

TEST(SymmetryCut, ABodyWhollyBeyondThePlanesIsAnInputErrorAtItsShape) {
  const case_file::Case c = elastic_case(box("beyond", "[-2 um, 0, 0]", "[-1 um, 1 um, 1 um]"));
  std::vector<SeededBody> seeded = seed_bodies(c);
  const InputError e =
      input_error([&] { cut_at_planes(c, kQuarter, "the test's planes", seeded); });
  EXPECT_EQ(e.key(), "bodies.beyond.shape");
  EXPECT_TRUE(contains(e.message(), "body 'beyond' lies wholly beyond the test's planes"));
}

}  // namespace
}  // namespace coldspray::bodies
