// Coarsened seeding (geometry/seeding.hpp, docs/mpm.md "Coarsened seeding"): against seed() on
// the same lattice, the points tile the same sites once each, keep seed()'s surface points and
// volumes, and coarsen only away from the fine region.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "geometry/seeding.hpp"

namespace coldspray::geometry {
namespace {

using Site = std::tuple<long, long, long>;

// The lattice index of the site of spacing s at x (sites at (i + 1/2) s; y = 0 in r-z).
Site site_of(const Vec3& x, double s, bool axi) {
  return {std::lround(x.x() / s - 0.5), axi ? 0 : std::lround(x.y() / s - 0.5),
          std::lround(x.z() / s - 0.5)};
}

// How many times each of seed()'s sites is covered by a coarsened point's cube.
std::map<Site, int> coverage(const SeededPoints& p, double s, bool axi) {
  std::map<Site, int> covered;
  for (std::size_t q = 0; q < p.position.size(); ++q) {
    const long n = std::lround(p.size[q] / s);
    const Vec3 first = p.position[q] - 0.5 * (p.size[q] - s) * Vec3(1.0, axi ? 0.0 : 1.0, 1.0);
    for (long k = 0; k < n; ++k)
      for (long j = 0; j < (axi ? 1 : n); ++j)
        for (long i = 0; i < n; ++i) ++covered[site_of(first + s * Vec3(i, j, k), s, axi)];
  }
  return covered;
}

// Whether the cube of edge b centred at x, grown by b on every side (a cube of edge 3b; a square
// in the plane y = 0 in r-z), holds a point of the region: sampled on a 31-point lattice along each
// axis, whose spacing b / 10 is far below the distances the coarsening keeps. (Shrunk by a part in
// 1e9: a cube grown by its edge may just touch the region, within rounding.) A cube apart from the
// region's bounding box cannot meet the region; that exact test first keeps the sampling to the
// cubes near it (under the sanitizers the sampling of every cube took 40 s a test).
bool grown_cube_meets(const Shape& region, const Vec3& x, double b, bool axi) {
  const Bounds box = bounding_box(region);
  const Vec3 reach = 1.5 * b * (1.0 - 1e-9) * Vec3(1.0, axi ? 0.0 : 1.0, 1.0);
  if (((x + reach).array() < box.min.array()).any() ||
      ((x - reach).array() > box.max.array()).any())
    return false;
  constexpr int n = 31;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < (axi ? 1 : n); ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 f = Vec3(i, axi ? 0.5 * (n - 1) : j, k) / (n - 1) - Vec3::Constant(0.5);
        const Vec3 y = x + 3.0 * b * (1.0 - 1e-9) * Vec3(f.x(), axi ? 0.0 : f.y(), f.z());
        if (contains(region, y)) return true;
      }
  return false;
}

void expect_same_body(const Shape& shape, double s, bool axi, int levels, const Shape& fine) {
  const Lattice lattice{Vec3::Zero(), s, axi};
  const SeededPoints uniform = seed(shape, lattice);
  const SeededPoints coarse = seed_coarsened(shape, lattice, levels, fine);
  // Fewer points, the same sites each covered once.
  EXPECT_LT(coarse.position.size(), uniform.position.size() / 2);
  const auto covered = coverage(coarse, s, axi);
  ASSERT_EQ(covered.size(), uniform.position.size());
  for (const Vec3& x : uniform.position) EXPECT_EQ(covered.at(site_of(x, s, axi)), 1);
  // The same volume (a ring's is linear in r, so a block's is its sites' sum in r-z too).
  const double v0 = std::accumulate(uniform.volume.begin(), uniform.volume.end(), 0.0);
  const double v1 = std::accumulate(coarse.volume.begin(), coarse.volume.end(), 0.0);
  EXPECT_NEAR(v1, v0, 1e-10 * v0);  // summation rounding over ~1e5 terms
  // The same surface points, with the same flags; every coarse point off the surface, its edge
  // at most 2^levels spacings, and away from the fine region's box by at least its edge.
  std::map<Site, std::uint8_t> surface;
  for (std::size_t q = 0; q < uniform.position.size(); ++q)
    if (uniform.outside[q]) surface[site_of(uniform.position[q], s, axi)] = uniform.outside[q];
  std::size_t coarse_surface = 0, coarser = 0;
  for (std::size_t q = 0; q < coarse.position.size(); ++q) {
    if (coarse.size[q] == s) {
      if (coarse.outside[q]) {
        ++coarse_surface;
        EXPECT_EQ(surface.at(site_of(coarse.position[q], s, axi)), coarse.outside[q]);
      }
      continue;
    }
    ++coarser;
    EXPECT_EQ(coarse.outside[q], 0);
    EXPECT_LE(coarse.size[q], std::ldexp(s, levels) * (1 + 1e-12));
    EXPECT_FALSE(grown_cube_meets(fine, coarse.position[q], coarse.size[q], axi))
        << "a point of edge " << coarse.size[q] << " at " << coarse.position[q].transpose();
  }
  EXPECT_EQ(coarse_surface, surface.size());
  EXPECT_GT(coarser, 0u);
}

// The thesis' substrate (30 x 10 um cylinder, Table 5.3) at 0.25 um, fine under a 14 um
// particle's footprint.
TEST(CoarsenedSeeding, A3dSubstrateTilesTheSameSitesOnce) {
  const Cylinder substrate{Vec3(0, 0, -10e-6), 15e-6, 10e-6};
  const Cylinder fine{Vec3(0, 0, -5e-6), 8e-6, 5e-6};
  expect_same_body(substrate, 0.25e-6, false, 2, fine);
}

// The fine region is a cylinder, not the box around it: cubes in the box's corners, beyond the
// cylinder by more than their edge, are coarse (a quarter substrate, as the 3D quarter impact).
TEST(CoarsenedSeeding, CoarsensTheCornersOfTheBoxAroundACylindricalFineRegion) {
  const double s = 0.25e-6;
  const Cylinder substrate{Vec3(0, 0, -10e-6), 15e-6, 10e-6};
  const Cylinder fine{Vec3(0, 0, -5e-6), 8e-6, 5e-6};
  const SeededPoints coarse = seed_coarsened(substrate, Lattice{Vec3::Zero(), s, false}, 2, fine);
  const Bounds box = bounding_box(fine);
  std::size_t in_corners = 0;
  for (std::size_t q = 0; q < coarse.position.size(); ++q) {
    const Vec3& x = coarse.position[q];
    if (coarse.size[q] == s || x.z() < box.min.z()) continue;
    // Within the box's footprint: the old rule (the box) kept every such point fine.
    if (std::abs(x.x()) < box.max.x() && std::abs(x.y()) < box.max.y()) ++in_corners;
  }
  EXPECT_GT(in_corners, 100u);
  expect_same_body(substrate, s, false, 2, fine);
}

TEST(CoarsenedSeeding, AnRzSubstrateTilesTheSameSitesOnce) {
  const Cylinder substrate{Vec3(0, 0, -10e-6), 15e-6, 10e-6};
  const Cylinder fine{Vec3(0, 0, -5e-6), 8e-6, 5e-6};
  expect_same_body(substrate, 0.125e-6, true, 3, fine);
}

TEST(CoarsenedSeeding, ABoxAndASphereTileTheSameSitesOnce) {
  const Box fine{Vec3(-1e-6, -1e-6, -1e-6), Vec3(1e-6, 1e-6, 1e-6)};
  expect_same_body(Box{Vec3(-6e-6, -5e-6, -4e-6), Vec3(6e-6, 5e-6, 4e-6)}, 0.25e-6, false, 2, fine);
  expect_same_body(Sphere{Vec3(0.1e-6, 0, 0), 6e-6}, 0.25e-6, false, 3, fine);
}

}  // namespace
}  // namespace coldspray::geometry
