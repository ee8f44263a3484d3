#include "geometry/seeding.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace coldspray::geometry {

namespace {

// Index range [lo, hi] of lattice sites origin + (i + 1/2) s within [min, max].
std::array<long, 2> site_range(double min, double max, double origin, double s) {
  return {static_cast<long>(std::floor((min - origin) / s - 0.5)),
          static_cast<long>(std::ceil((max - origin) / s - 0.5))};
}

}  // namespace

SeededPoints seed(const case_file::Shape& shape, const Lattice& lattice) {
  const double s = lattice.spacing;
  const Bounds box = bounding_box(shape);
  std::array<std::array<long, 2>, 3> range;
  for (int d = 0; d < 3; ++d) range[d] = site_range(box.min[d], box.max[d], lattice.origin[d], s);
  Vec3 origin = lattice.origin;
  if (lattice.axisymmetric) {
    origin.x() = 0.0;
    range[0] = {0, static_cast<long>(std::ceil(box.max.x() / s - 0.5))};
    range[1] = {0, 0};
    origin.y() = -0.5 * s;  // so that the single y site sits at y = 0
  }
  auto site = [&](long i, long j, long k) {
    return Vec3(origin.x() + (i + 0.5) * s, origin.y() + (j + 0.5) * s, origin.z() + (k + 0.5) * s);
  };
  // Neighbours along y do not exist in r-z; a neighbour across the axis (r < 0) mirrors to the
  // inside of an axisymmetric shape, so the axis is never flagged as a surface.
  const int axes = lattice.axisymmetric ? 2 : 3;
  const std::array<int, 3> axis_of = {0, 2, 1};

  SeededPoints out;
  for (long k = range[2][0]; k <= range[2][1]; ++k)
    for (long j = range[1][0]; j <= range[1][1]; ++j)
      for (long i = range[0][0]; i <= range[0][1]; ++i) {
        const Vec3 x = site(i, j, k);
        if (!contains(shape, x)) continue;
        std::uint8_t outside = 0;
        for (int a = 0; a < axes; ++a) {
          const int axis = axis_of[a];
          Vec3 step = Vec3::Zero();
          step[axis] = s;
          if (!contains(shape, x - step)) outside |= static_cast<std::uint8_t>(1u << (2 * axis));
          if (!contains(shape, x + step))
            outside |= static_cast<std::uint8_t>(1u << (2 * axis + 1));
        }
        out.position.push_back(x);
        out.volume.push_back(lattice.axisymmetric ? 2.0 * std::numbers::pi * x.x() * s * s
                                                  : s * s * s);
        out.outside.push_back(outside);
      }
  return out;
}

}  // namespace coldspray::geometry
