#include "bodies/describe_point.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace coldspray::bodies {

std::string describe_point(const Bodies& s, std::size_t p) {
  const auto body = std::find_if(s.bodies.begin(), s.bodies.end(),
                                 [p](const BodyRange& b) { return p >= b.begin && p < b.end; });
  return fmt::format("body '{}', point {} at ({:.4g}, {:.4g}, {:.4g}) um, t = {:.6g} ns",
                     body->name, s.points.id[p], s.points.position[0][p] * 1e6,
                     s.points.position[1][p] * 1e6, s.points.position[2][p] * 1e6, s.time * 1e9);
}

}  // namespace coldspray::bodies
