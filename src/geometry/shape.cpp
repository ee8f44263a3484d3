#include "geometry/shape.hpp"

#include <type_traits>

namespace coldspray::geometry {

bool contains(const case_file::Shape& shape, const Vec3& x) {
  return std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, case_file::Sphere>) {
          return (x - s.center).squaredNorm() <= s.radius * s.radius;
        } else if constexpr (std::is_same_v<S, case_file::Cylinder>) {
          const double dx = x.x() - s.base_center.x(), dy = x.y() - s.base_center.y();
          const double dz = x.z() - s.base_center.z();
          return dx * dx + dy * dy <= s.radius * s.radius && dz >= 0.0 && dz <= s.height;
        } else {
          return (x.array() >= s.min.array()).all() && (x.array() <= s.max.array()).all();
        }
      },
      shape);
}

Bounds bounding_box(const case_file::Shape& shape) {
  return std::visit(
      [](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, case_file::Sphere>) {
          const Vec3 r = Vec3::Constant(s.radius);
          return Bounds{s.center - r, s.center + r};
        } else if constexpr (std::is_same_v<S, case_file::Cylinder>) {
          const Vec3 r(s.radius, s.radius, 0.0);
          return Bounds{s.base_center - r, s.base_center + r + Vec3(0, 0, s.height)};
        } else {
          return Bounds{s.min, s.max};
        }
      },
      shape);
}

}  // namespace coldspray::geometry
