// The points of a body's absorbing faces and their dashpots (bodies/seed_bodies.cpp, thesis
// §3.5.5, eqs 3.45-3.46 with a = b = 1), by hand: rho c_p per unit area along a face's normal,
// rho c_s along its tangents, one face area per outside neighbour, and in r-z the ring's area.
// Also the area a surface point stands for (bodies/point_area.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bodies/point_area.hpp"
#include "bodies/seed_bodies.hpp"
#include "elastic_case.hpp"
#include "geometry/seeding.hpp"
#include "units.hpp"

namespace coldspray::bodies {
namespace {

using testing::box;
using testing::elastic_case;
using testing::kPWave;
using testing::kSWave;
using testing::laid_out;

using coldspray::testing::um;
constexpr double kFace = 0.25e-12;  // (0.5 um)^2, m^2

// A 2 x 2 x 1 um slab of 4 x 4 x 2 points with the given absorbing faces.
Bodies slab(const std::string& faces) {
  return laid_out(elastic_case(box("slab", "[0, 0, 0]", "[2 um, 2 um, 1 um]", "    absorbing: ") +
                               faces + "\n"));
}

const AbsorbingPoint& at(const Bodies& s, double x, double y, double z) {
  for (const AbsorbingPoint& a : s.absorbing) {
    const std::size_t p = a.point;
    if (std::abs(s.points.position[0][p] - x) < 1e-12 &&
        std::abs(s.points.position[1][p] - y) < 1e-12 &&
        std::abs(s.points.position[2][p] - z) < 1e-12)
      return a;
  }
  throw std::runtime_error("no absorbing point there");
}

TEST(AbsorbingFaces, TheBottomFacesPointsGetANormalAndTwoTangentialDashpots) {
  const Bodies s = slab("[bottom]");
  ASSERT_EQ(s.absorbing.size(), 16u);  // the layer z = 0.25 um
  for (const AbsorbingPoint& a : s.absorbing) {
    EXPECT_NEAR(s.points.position[2][a.point], 0.25 * um, 1e-18);
    // 2700 kg/m^3 x 6118.18 m/s x 0.25 um^2 = 4.12977e-6 N s/m along z, and with 3103.16 m/s
    // 2.09464e-6 N s/m along x and y, even at the bottom's edges: only the bottom absorbs.
    EXPECT_NEAR(a.damping[2], 4.12977e-6, 1e-11);
    EXPECT_NEAR(a.damping[0], 2.09464e-6, 1e-11);
    EXPECT_NEAR(a.damping[1], 2.09464e-6, 1e-11);
    EXPECT_EQ(a.absorbed, 0.0);
  }
  EXPECT_NEAR(2700.0 * kPWave * kFace, 4.12977e-6, 1e-11);  // the numbers above
  EXPECT_NEAR(2700.0 * kSWave * kFace, 2.09464e-6, 1e-11);
}

TEST(AbsorbingFaces, AnEdgeOrCornerPointAddsAFaceAreaForEachOutsideNeighbour) {
  const Bodies s = slab("[bottom, side]");
  // The bottom layer's 16 and the 12 round the top layer's rim.
  EXPECT_EQ(s.absorbing.size(), 28u);
  // A corner of the bottom: outside along -x, -y and -z, three areas, each axis normal to one:
  // rho (c_p + 2 c_s) (0.5 um)^2 = 8.31904e-6 N s/m on every axis.
  const AbsorbingPoint& corner = at(s, 0.25 * um, 0.25 * um, 0.25 * um);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(corner.damping[d], 8.31904e-6, 1e-11) << "axis " << d;
  // The bottom's edge along x: outside along -y and -z. Along x only tangents, 2 rho c_s
  // (0.5 um)^2 = 4.18927e-6; along y and z one normal and one tangent, rho (c_p + c_s)
  // (0.5 um)^2 = 6.22441e-6 N s/m.
  const AbsorbingPoint& edge = at(s, 0.75 * um, 0.25 * um, 0.25 * um);
  EXPECT_NEAR(edge.damping[0], 4.18927e-6, 1e-11);
  EXPECT_NEAR(edge.damping[1], 6.22441e-6, 1e-11);
  EXPECT_NEAR(edge.damping[2], 6.22441e-6, 1e-11);
  // A side point of the top layer: outside along +x only (the top does not absorb).
  const AbsorbingPoint& side = at(s, 1.75 * um, 0.75 * um, 0.75 * um);
  EXPECT_NEAR(side.damping[0], 4.12977e-6, 1e-11);
  EXPECT_NEAR(side.damping[1], 2.09464e-6, 1e-11);
  EXPECT_NEAR(side.damping[2], 2.09464e-6, 1e-11);
}

TEST(AbsorbingFaces, TheTopIsTheLayerAtTheLargestZ) {
  const Bodies s = slab("[top]");
  ASSERT_EQ(s.absorbing.size(), 16u);
  for (const AbsorbingPoint& a : s.absorbing)
    EXPECT_NEAR(s.points.position[2][a.point], 0.75 * um, 1e-18);
}

TEST(AbsorbingFaces, InRzAFacesAreaIsTheRingsAndTheHoopHasNoDashpot) {
  // A disc of radius 1 um and height 1 um: points at r = 0.25 and 0.75 um. The bottom's face of
  // the point at r is 2 pi r (0.5 um), so rho c_p 2 pi r (0.5 um) = 1.2974055e-5 N s/m at
  // r = 0.25 um along z, three times that at 0.75 um. The axis is no side: only the outer
  // column is on it.
  const std::string disc =
      "  - name: disc\n    material: elastic-al\n"
      "    shape: {type: cylinder, base_center: [0, 0, 0], radius: 1 um, height: 1 um}\n"
      "    spacing: 0.5 um\n    absorbing: ";
  const std::string rz = "solver:\n  geometry: axisymmetric\n  end_time: 1 ns\n";
  const Bodies bottom = laid_out(elastic_case(disc + "[bottom]\n", rz));
  ASSERT_EQ(bottom.absorbing.size(), 2u);
  for (const AbsorbingPoint& a : bottom.absorbing) {
    const double r = bottom.points.position[0][a.point];
    EXPECT_NEAR(a.damping[2], 1.2974055e-5 * r / (0.25 * um), 1e-10);
    EXPECT_NEAR(a.damping[0], 1.2974055e-5 * kSWave / kPWave * r / (0.25 * um), 1e-10);
    EXPECT_EQ(a.damping[1], 0.0);
  }
  const Bodies side = laid_out(elastic_case(disc + "[side]\n", rz));
  ASSERT_EQ(side.absorbing.size(), 2u);
  for (const AbsorbingPoint& a : side.absorbing)
    EXPECT_NEAR(side.points.position[0][a.point], 0.75 * um, 1e-18);
}

TEST(AbsorbingFaces, FaceBitsAreTheOutsideNeighboursOfEachFace) {
  using case_file::BodyFace;
  EXPECT_EQ(faces_bits({BodyFace::Bottom}), geometry::kMinusZ);
  EXPECT_EQ(faces_bits({BodyFace::Top}), geometry::kPlusZ);
  EXPECT_EQ(faces_bits({BodyFace::Side}), 1 + 2 + 4 + 8);
  EXPECT_EQ(faces_bits({BodyFace::Bottom, BodyFace::Side, BodyFace::Top}), 63);
  EXPECT_EQ(faces_bits({}), 0);
}

TEST(PointArea, IsTheCubesFaceIn3dAndTheRingsInRz) {
  Points P;
  P.resize(2);
  P.volume0[0] = 0.125e-18, P.J[0] = 1.0;  // a cube of 0.5 um: (0.5 um)^2
  P.volume0[1] = 0.125e-18, P.J[1] = 8.0;  // compressed to twice its edge: (1 um)^2
  EXPECT_NEAR(point_area(P, 0, false), 0.25e-12, 1e-27);
  EXPECT_NEAR(point_area(P, 1, false), 1e-12, 1e-27);
  // In r-z, the ring at r = 0.75 um of a 0.5 um square: 2 pi r 0.5 um = 2.35619e-12 m^2.
  P.position[0][0] = 0.75e-6;
  P.volume0[0] = 2.0 * std::numbers::pi * 0.75e-6 * 0.25e-12;
  EXPECT_NEAR(point_area(P, 0, true), 2.35619449e-12, 1e-20);
}

}  // namespace
}  // namespace coldspray::bodies
