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

}  // namespace coldspray::geometry
