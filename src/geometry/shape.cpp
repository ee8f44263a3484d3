#include "geometry/shape.hpp"

#include <algorithm>
#include <type_traits>

namespace coldspray::geometry {

bool contains(const Shape& shape, const Vec3& x) {
  return std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Sphere>) {
          return (x - s.center).squaredNorm() <= s.radius * s.radius;
        } else if constexpr (std::is_same_v<S, Cylinder>) {
          const double dx = x.x() - s.base_center.x(), dy = x.y() - s.base_center.y();
          const double dz = x.z() - s.base_center.z();
          return dx * dx + dy * dy <= s.radius * s.radius && dz >= 0.0 && dz <= s.height;
        } else {
          return (x.array() >= s.min.array()).all() && (x.array() <= s.max.array()).all();
        }
      },
      shape);
}

bool meets(const Shape& shape, const Bounds& box) {
  // The squared distance from a to the interval [lo, hi].
  auto gap2 = [](double a, double lo, double hi) {
    const double g = a - std::clamp(a, lo, hi);
    return g * g;
  };
  return std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Sphere>) {
          double d2 = 0.0;
          for (int d = 0; d < 3; ++d) d2 += gap2(s.center[d], box.min[d], box.max[d]);
          return d2 <= s.radius * s.radius;
        } else if constexpr (std::is_same_v<S, Cylinder>) {
          const double bottom = s.base_center.z(), top = bottom + s.height;
          if (box.max.z() < bottom || box.min.z() > top) return false;
          const double d2 = gap2(s.base_center.x(), box.min.x(), box.max.x()) +
                            gap2(s.base_center.y(), box.min.y(), box.max.y());
          return d2 <= s.radius * s.radius;
        } else {
          return (box.min.array() <= s.max.array()).all() &&
                 (box.max.array() >= s.min.array()).all();
        }
      },
      shape);
}

}  // namespace coldspray::geometry
