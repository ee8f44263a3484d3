#include "geometry/seeding.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "core/interrupt.hpp"

namespace coldspray::geometry {

namespace {

// The seeding reads the stop flag once a row of lattice sites (of cubes, coarsened): a row is at
// most the body's width in sites, and a body of 1e7 points has a few thousand rows.
constexpr const char* kSeeding = "seeding the bodies";

// Index range [lo, hi] of lattice sites origin + (i + 1/2) s within [min, max].
std::array<long, 2> site_range(double min, double max, double origin, double s) {
  return {static_cast<long>(std::floor((min - origin) / s - 0.5)),
          static_cast<long>(std::ceil((max - origin) / s - 0.5))};
}

// The point's volume: a cube of edge a, or in r-z the ring of square section a x a at radius x.
double cell_volume(const Vec3& x, double a, bool axisymmetric) {
  return axisymmetric ? 2.0 * std::numbers::pi * x.x() * a * a : a * a * a;
}

// Lattice sites lie at origin + (i + 1/2) s; in r-z in the plane y = 0 from r = s/2.
Vec3 lattice_origin(const Lattice& lattice) {
  Vec3 origin = lattice.origin;
  if (lattice.axisymmetric) {
    origin.x() = 0.0;
    origin.y() = -0.5 * lattice.spacing;  // so that the single y site sits at y = 0
  }
  return origin;
}

}  // namespace

void SeededPoints::add_site(const Shape& shape, const Vec3& x, double s, bool axisymmetric) {
  // Neighbours along y do not exist in r-z; a neighbour across the axis (r < 0) mirrors to the
  // inside of an axisymmetric shape, so the axis is never flagged as a surface.
  const int axes = axisymmetric ? 2 : 3;
  const std::array<int, 3> axis_of = {0, 2, 1};
  std::uint8_t flags = 0;
  for (int a = 0; a < axes; ++a) {
    const int axis = axis_of[a];
    Vec3 step = Vec3::Zero();
    step[axis] = s;
    if (!contains(shape, x - step)) flags |= static_cast<std::uint8_t>(1u << (2 * axis));
    if (!contains(shape, x + step)) flags |= static_cast<std::uint8_t>(1u << (2 * axis + 1));
  }
  position.push_back(x);
  volume.push_back(cell_volume(x, s, axisymmetric));
  size.push_back(s);
  outside.push_back(flags);
}

void SeededPoints::add_block(const Vec3& x, double b, bool axisymmetric) {
  position.push_back(x);
  volume.push_back(cell_volume(x, b, axisymmetric));
  size.push_back(b);
  outside.push_back(0);
}

SeededPoints seed(const Shape& shape, const Lattice& lattice) {
  const double s = lattice.spacing;
  const Bounds box = bounding_box(shape);
  std::array<std::array<long, 2>, 3> range;
  for (int d = 0; d < 3; ++d) range[d] = site_range(box.min[d], box.max[d], lattice.origin[d], s);
  const Vec3 origin = lattice_origin(lattice);
  if (lattice.axisymmetric) {
    range[0] = {0, static_cast<long>(std::ceil(box.max.x() / s - 0.5))};
    range[1] = {0, 0};
  }
  SeededPoints out;
  for (long k = range[2][0]; k <= range[2][1]; ++k)
    for (long j = range[1][0]; j <= range[1][1]; ++j) {
      stop_set_up_if_interrupted(kSeeding);
      for (long i = range[0][0]; i <= range[0][1]; ++i) {
        const Vec3 x = origin + s * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (contains(shape, x)) out.add_site(shape, x, s, lattice.axisymmetric);
      }
    }
  return out;
}

namespace {

// The cubes of the coarsened lattice, split down to single sites where they must be.
class Coarsener {
 public:
  Coarsener(const Shape& shape, const Lattice& lattice, const Shape& fine)
      : shape_(shape), fine_(fine), s_(lattice.spacing), axisymmetric_(lattice.axisymmetric) {}

  // The cube of edge b whose lowest corner is lo: one point if it may be, else its 8 (4 in r-z)
  // halves, down to single lattice sites.
  void add(const Vec3& lo, double b, SeededPoints& out) const {
    const Vec3 centre = lo + 0.5 * b * in_plane();
    if (b <= 1.5 * s_) {  // a single site
      if (contains(shape_, centre)) out.add_site(shape_, centre, s_, axisymmetric_);
      return;
    }
    if (!near_fine(lo, b) && inside_off_surface(lo, b)) {
      out.add_block(centre, b, axisymmetric_);
      return;
    }
    const double h = 0.5 * b;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < (axisymmetric_ ? 1 : 2); ++j)
        for (int i = 0; i < 2; ++i) add(lo + h * Vec3(i, j, k), h, out);
  }

 private:
  // The directions a cube spans: y has a single site in r-z.
  Vec3 in_plane() const { return axisymmetric_ ? Vec3(1.0, 0.0, 1.0) : Vec3::Ones(); }

  // Whether the cube, grown by its own edge on every side, meets the fine region: each level of
  // coarsening starts at least its own edge away from the level below. (In r-z the cube lies in
  // the plane y = 0 of the sites.)
  bool near_fine(const Vec3& lo, double b) const {
    Bounds grown{lo - b * in_plane(), lo + 2.0 * b * in_plane()};
    return meets(fine_, grown);
  }

  // Whether the cube grown by one spacing lies inside the shape: its corners do, the shapes
  // being convex. None of its sites is then on the surface, whose points stay seed()'s.
  bool inside_off_surface(const Vec3& lo, double b) const {
    const Vec3 grown_lo = lo - s_ * in_plane(), span = (b + 2.0 * s_) * in_plane();
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 x = grown_lo + Vec3((corner & 1) * span.x(), ((corner >> 1) & 1) * span.y(),
                                     ((corner >> 2) & 1) * span.z());
      if (!contains(shape_, x)) return false;
    }
    return true;
  }

  const Shape& shape_;
  const Shape& fine_;
  double s_;
  bool axisymmetric_;
};

}  // namespace

SeededPoints seed_coarsened(const Shape& shape, const Lattice& lattice, int levels,
                            const Shape& fine) {
  const double s = lattice.spacing, b = std::ldexp(s, levels);
  const Bounds box = bounding_box(shape);
  // The cubes of edge b = 2^levels s tile the lattice from its origin: cube n spans the sites
  // n 2^levels to (n + 1) 2^levels - 1.
  Vec3 origin = lattice_origin(lattice);
  std::array<std::array<long, 2>, 3> range;
  for (int d = 0; d < 3; ++d)
    range[d] = {static_cast<long>(std::floor((box.min[d] - origin[d]) / b)),
                static_cast<long>(std::floor((box.max[d] - origin[d]) / b))};
  if (lattice.axisymmetric) {
    range[0][0] = 0;
    range[1] = {0, 0};
  }
  const Coarsener coarsener(shape, lattice, fine);
  SeededPoints out;
  for (long k = range[2][0]; k <= range[2][1]; ++k)
    for (long j = range[1][0]; j <= range[1][1]; ++j) {
      stop_set_up_if_interrupted(kSeeding);
      for (long i = range[0][0]; i <= range[0][1]; ++i) {
        Vec3 lo = origin + b * Vec3(i, j, k);
        if (lattice.axisymmetric) lo.y() = 0.0;  // the plane of the sites
        coarsener.add(lo, b, out);
      }
    }
  return out;
}

}  // namespace coldspray::geometry
