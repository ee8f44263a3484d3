// Turning a case's bodies into points (bodies/seed_bodies.hpp), counted by hand: which lattice
// sites a shape keeps, what each point weighs and carries at t = 0, how the bodies are laid out
// one after another, and the set-up errors a body's shape or spacing can raise.
#include "bodies/seed_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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
using testing::kPWave;
using testing::laid_out;

using coldspray::testing::um;

TEST(SeedBodies, ABoxHasAPointAtEveryLatticeSiteInsideItEachWithItsCubesMass) {
  // Sites at (i + 1/2) 0.5 um: 4 x 2 x 2 of them in a 2 x 1 x 1 um box.
  const case_file::Case c =
      elastic_case(box("block", "[0, 0, 0]", "[2 um, 1 um, 1 um]",
                       "    velocity: [1000 m/s, 0, 0]\n    temperature: 400 K\n"));
  const std::vector<SeededBody> seeded = seed_bodies(c);
  ASSERT_EQ(seeded.size(), 1u);
  ASSERT_EQ(seeded[0].points.position.size(), 16u);
  // The bounds of the points' cubes are the box's.
  EXPECT_NEAR(seeded[0].min.norm(), 0.0, 1e-18);
  EXPECT_NEAR((seeded[0].max - case_file::Vec3(2 * um, um, um)).norm(), 0.0, 1e-18);

  Bodies s;
  lay_out_bodies(c, seeded, s);
  const Points& P = s.points;
  ASSERT_EQ(P.size(), 16u);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].begin, 0u);
  EXPECT_EQ(s.bodies[0].end, 16u);
  EXPECT_EQ(s.bodies[0].name, "block");
  EXPECT_EQ(s.bodies[0].spacing, 0.5 * um);
  double xs = 0.0;
  for (std::size_t p = 0; p < 16; ++p) {
    EXPECT_NEAR(P.mass[p], kPointMass, 1e-30);
    EXPECT_NEAR(P.volume0[p], 0.125 * um * um * um, 1e-33);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(P.half_width[d][p], 0.25 * um);
    EXPECT_EQ(P.velocity[0][p], 1000.0);
    EXPECT_EQ(P.velocity[2][p], 0.0);
    EXPECT_EQ(P.temperature[p], 400.0);
    EXPECT_EQ(P.J[p], 1.0);
    EXPECT_EQ(P.stress[kXX][p], 0.0);
    EXPECT_NEAR(P.sound_speed[p], kPWave, 1e-3);
    EXPECT_EQ(P.initial_z[p], P.position[2][p]);
    EXPECT_EQ(P.id[p], p);
    EXPECT_EQ(P.body[p], 0u);
    EXPECT_EQ(P.surface[p], 1u) << "a block two points thick is all surface";
    xs += P.position[0][p];
  }
  EXPECT_NEAR(xs, 4.0 * (0.25 + 0.75 + 1.25 + 1.75) * um, 1e-18);
  // c + |v| at t = 0.
  EXPECT_NEAR(s.max_signal_speed, kPWave + 1000.0, 1e-3);
  EXPECT_NEAR(s.bodies[0].initial_diameter, 2 * um, 1e-18);  // its x extent, 1.5 um + a spacing
  EXPECT_TRUE(s.absorbing.empty());
}

TEST(SeedBodies, OnlyTheOuterLayerOfABlockIsItsSurface) {
  // 4 x 4 x 4 points; the 2 x 2 x 2 within have all six neighbours inside.
  const Bodies s = laid_out(elastic_case(box("cube", "[0, 0, 0]", "[2 um, 2 um, 2 um]")));
  ASSERT_EQ(s.points.size(), 64u);
  std::size_t surface = 0;
  for (std::size_t p = 0; p < 64; ++p) {
    surface += s.points.surface[p];
    const bool inner = std::abs(s.points.position[0][p] - 1 * um) < 0.5 * um &&
                       std::abs(s.points.position[1][p] - 1 * um) < 0.5 * um &&
                       std::abs(s.points.position[2][p] - 1 * um) < 0.5 * um;
    EXPECT_EQ(s.points.surface[p], inner ? 0u : 1u) << "point " << p;
  }
  EXPECT_EQ(surface, 56u);
}

TEST(SeedBodies, ASphereKeepsTheSitesWithinItsRadius) {
  // Sites at +-0.25 and +-0.75 um on each axis; within 1 um of the centre: the 8 with
  // x^2 + y^2 + z^2 = 0.1875 um^2 and the 24 with one coordinate +-0.75 (0.6875 um^2), not those
  // with two (1.1875 um^2).
  const Bodies s =
      laid_out(elastic_case("  - name: ball\n    material: elastic-al\n"
                            "    shape: {type: sphere, center: [0, 0, 0], radius: 1 um}\n"
                            "    spacing: 0.5 um\n"));
  ASSERT_EQ(s.points.size(), 32u);
  double mass = 0.0;
  for (std::size_t p = 0; p < 32; ++p) {
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d) r2 += s.points.position[d][p] * s.points.position[d][p];
    EXPECT_LT(r2, 1 * um * um);
    mass += s.points.mass[p];
  }
  EXPECT_NEAR(mass, 32 * kPointMass, 1e-28);
}

TEST(SeedBodies, AnAxisymmetricPointIsARingOfItsRadius) {
  // A cylinder of radius 1 um and height 1 um in r-z: points at r = 0.25 and 0.75 um, z = 0.25
  // and 0.75 um, each the ring 2 pi r (0.5 um)^2. The rings add up to pi R^2 h exactly.
  const Bodies s = laid_out(elastic_case(
      "  - name: disc\n    material: elastic-al\n"
      "    shape: {type: cylinder, base_center: [0, 0, 0], radius: 1 um, height: 1 um}\n"
      "    spacing: 0.5 um\n",
      "solver:\n  geometry: axisymmetric\n  end_time: 1 ns\n"));
  ASSERT_EQ(s.points.size(), 4u);
  double mass = 0.0;
  for (std::size_t p = 0; p < 4; ++p) {
    const double r = s.points.position[0][p];
    EXPECT_TRUE(std::abs(r - 0.25 * um) < 1e-18 || std::abs(r - 0.75 * um) < 1e-18) << r;
    EXPECT_EQ(s.points.position[1][p], 0.0);
    EXPECT_NEAR(s.points.mass[p], 2700.0 * 2.0 * std::numbers::pi * r * 0.25 * um * um, 1e-30);
    mass += s.points.mass[p];
  }
  EXPECT_NEAR(mass, 8.4823001647e-15, 1e-24);  // 2700 kg/m^3 x pi (1 um)^2 x 1 um
  // Mirrored at the axis: the diameter is twice the largest radius plus a spacing.
  ASSERT_TRUE(s.bodies[0].mirror_plane[0]);
  EXPECT_EQ(*s.bodies[0].mirror_plane[0], 0.0);
  EXPECT_NEAR(s.bodies[0].initial_diameter, 2 * um, 1e-18);
}

TEST(SeedBodies, BodiesAreLaidOutOneAfterAnotherInTheCasesOrder) {
  const Bodies s = laid_out(elastic_case(
      box("first", "[0, 0, 0]", "[2 um, 1 um, 1 um]", "    velocity: [0, 0, -300 m/s]\n") +
      box("second", "[0, 0, -2 um]", "[1 um, 1 um, -1 um]")));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].name, "first");
  EXPECT_EQ(s.bodies[0].end, 16u);
  EXPECT_EQ(s.bodies[1].name, "second");
  EXPECT_EQ(s.bodies[1].begin, 16u);
  EXPECT_EQ(s.bodies[1].end, 24u);  // 2 x 2 x 2
  for (std::size_t p = 0; p < 24; ++p) {
    EXPECT_EQ(s.points.body[p], p < 16 ? 0u : 1u);
    EXPECT_EQ(s.points.id[p], p < 16 ? p : p - 16) << "the index among its body's points";
    EXPECT_EQ(s.points.velocity[2][p], p < 16 ? -300.0 : 0.0);
  }
  EXPECT_EQ(s.bodies[0].initial_velocity[2], -300.0);
  EXPECT_EQ(s.contact_impulse.size(), 4u);  // one for each ordered pair
  // The moving body's penetration is measured along -z over its height, 0.5 um plus a spacing;
  // the body at rest has none.
  EXPECT_EQ(s.bodies[0].penetration.direction[2], -1.0);
  EXPECT_NEAR(s.bodies[0].penetration.size, 1 * um, 1e-18);
  EXPECT_EQ(s.bodies[1].penetration.size, 0.0);
  EXPECT_NEAR(s.max_signal_speed, kPWave + 300.0, 1e-3);
}

TEST(SeedBodies, ACoarsenedBodyKeepsItsMassAndItsCoarsePointsAreTheirCubes) {
  // 8 x 8 x 8 sites; away from the fine corner, cubes of 2 x 2 x 2 sites off the surface become
  // one point of 1 um a side, 8 points' mass.
  const Bodies s = laid_out(elastic_case(box(
      "slab", "[0, 0, 0]", "[4 um, 4 um, 4 um]",
      "    coarsening: {levels: 1, fine: {type: box, min: [0, 0, 3.5 um], max: [0.5 um, 0.5 um, "
      "4 um]}}\n")));
  const Points& P = s.points;
  ASSERT_LT(P.size(), 512u);
  double mass = 0.0;
  std::size_t coarse = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    mass += P.mass[p];
    const double edge = 2.0 * P.half_width[0][p];
    EXPECT_NEAR(P.mass[p], 2700.0 * edge * edge * edge, 1e-12 * P.mass[p]) << "point " << p;
    if (edge > 0.75 * um) {
      ++coarse;
      EXPECT_NEAR(P.mass[p], 8 * kPointMass, 1e-28);
      EXPECT_EQ(P.surface[p], 0u);
    }
  }
  EXPECT_GT(coarse, 0u);
  EXPECT_EQ(P.size(), 512u - 7u * coarse);
  EXPECT_NEAR(mass, 512 * kPointMass, 1e-12 * mass);
}

TEST(SeedBodies, ABodyWithNoSiteInsideIsAnInputErrorAtItsSpacing) {
  // The sites nearest, 0.25 and 0.75 um, lie either side of the 0.3-0.45 um box.
  const case_file::Case c =
      elastic_case(box("speck", "[0.3 um, 0.3 um, 0.3 um]", "[0.45 um, 0.45 um, 0.45 um]"));
  const InputError e = input_error([&] { seed_bodies(c); });
  EXPECT_EQ(e.key(), "bodies.speck.spacing");
  EXPECT_TRUE(contains(e.message(), "body 'speck' has no points"));
}

TEST(SeedBodies, BodiesThatOverlapAreAnInputErrorButTouchingOnesAreNot) {
  const std::string lower = box("lower", "[0, 0, 0]", "[1 um, 1 um, 1 um]");
  // Face to face at z = 1 um: no point of one lies in the other.
  EXPECT_EQ(laid_out(elastic_case(lower + box("upper", "[0, 0, 1 um]", "[1 um, 1 um, 2 um]")))
                .points.size(),
            16u);
  const case_file::Case c =
      elastic_case(lower + box("upper", "[0, 0, 0.5 um]", "[1 um, 1 um, 2 um]"));
  const InputError e = input_error([&] { seed_bodies(c); });
  EXPECT_EQ(e.key(), "bodies.lower.shape");
  EXPECT_TRUE(contains(e.message(), "body 'lower' overlaps body 'upper' at t = 0"));
}

}  // namespace
}  // namespace coldspray::bodies
