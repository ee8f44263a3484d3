// geometry::meets (geometry/shape.hpp): whether a shape and an axis-aligned box share a point,
// against hand-worked boxes just inside and just outside each shape.
#include <gtest/gtest.h>

#include "geometry/shape.hpp"

namespace coldspray::geometry {
namespace {

Bounds box(const Vec3& lo, const Vec3& hi) { return Bounds{lo, hi}; }

TEST(ShapeMeets, ASphereMeetsABoxWhereTheBoxReachesWithinItsRadius) {
  const Sphere s{Vec3(0, 0, 0), 1.0};
  EXPECT_TRUE(meets(s, box(Vec3(-0.1, -0.1, -0.1), Vec3(0.1, 0.1, 0.1))));  // inside
  EXPECT_TRUE(meets(s, box(Vec3(0.9, -5, -5), Vec3(3, 5, 5))));             // a face cuts it
  // The corner (0.6, 0.6, 0.6) lies 1.039 from the centre; (0.5, 0.5, 0.5) 0.866.
  EXPECT_FALSE(meets(s, box(Vec3(0.6, 0.6, 0.6), Vec3(2, 2, 2))));
  EXPECT_TRUE(meets(s, box(Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2))));
  EXPECT_TRUE(meets(s, box(Vec3(-2, -2, -2), Vec3(2, 2, 2))));  // holding it whole
}

TEST(ShapeMeets, ACylinderMeetsABoxWhereBothItsHeightAndItsRadiusReach) {
  const Cylinder c{Vec3(1, 2, -1), 2.0, 3.0};  // axis x = 1, y = 2; z from -1 to 2
  // In the corner of the cylinder's bounding box, (1 + 1.5, 2 + 1.5) lies 2.12 from the axis.
  EXPECT_FALSE(meets(c, box(Vec3(2.5, 3.5, 0), Vec3(3, 4, 1))));
  // (1 + 1.4, 2 + 1.4) lies 1.98 from it.
  EXPECT_TRUE(meets(c, box(Vec3(2.4, 3.4, 0), Vec3(3, 4, 1))));
  EXPECT_FALSE(meets(c, box(Vec3(0, 1, 2.1), Vec3(2, 3, 3))));    // above the top
  EXPECT_FALSE(meets(c, box(Vec3(0, 1, -3), Vec3(2, 3, -1.1))));  // below the base
  EXPECT_TRUE(meets(c, box(Vec3(0, 1, 1.9), Vec3(2, 3, 3))));
  EXPECT_TRUE(meets(c, box(Vec3(-10, -10, -10), Vec3(10, 10, 10))));
}

TEST(ShapeMeets, ABoxMeetsABoxWhereTheirRangesOverlapOnEveryAxis) {
  const Box b{Vec3(0, 0, 0), Vec3(1, 2, 3)};
  EXPECT_TRUE(meets(b, box(Vec3(0.5, 1.5, 2.5), Vec3(4, 4, 4))));
  EXPECT_TRUE(meets(b, box(Vec3(1, 2, 3), Vec3(4, 4, 4))));  // touching at a corner
  EXPECT_FALSE(meets(b, box(Vec3(0.5, 2.1, 0.5), Vec3(4, 4, 4))));
  EXPECT_FALSE(meets(b, box(Vec3(-2, -2, -2), Vec3(-0.1, 4, 4))));
}

}  // namespace
}  // namespace coldspray::geometry
