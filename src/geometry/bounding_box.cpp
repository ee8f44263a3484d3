#include <type_traits>

#include "geometry/shape.hpp"

namespace coldspray::geometry {

Bounds bounding_box(const Shape& shape) {
  return std::visit(
      [](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Sphere>) {
          const Vec3 r = Vec3::Constant(s.radius);
          return Bounds{s.center - r, s.center + r};
        } else if constexpr (std::is_same_v<S, Cylinder>) {
          const Vec3 r(s.radius, s.radius, 0.0);
          return Bounds{s.base_center - r, s.base_center + r + Vec3(0, 0, s.height)};
        } else {
          return Bounds{s.min, s.max};
        }
      },
      shape);
}

}  // namespace coldspray::geometry
