#include <fmt/format.h>

#include <algorithm>

#include "bodies/bodies.hpp"
#include "core/error.hpp"

namespace coldspray::bodies {

void record_fault(Fault& fault, std::size_t p, const char* cause) {
#pragma omp critical(coldspray_fault)
  if (p < fault.point) {
    fault.point = p;
    fault.cause = cause;
  }
}

void raise_recorded_fault(const Bodies& s) {
  if (s.fault.point == std::numeric_limits<std::size_t>::max()) return;
  const std::size_t p = s.fault.point;
  const auto body = std::find_if(s.bodies.begin(), s.bodies.end(),
                                 [p](const BodyRange& b) { return p >= b.begin && p < b.end; });
  throw RunFault(fmt::format(
      "body '{}', point {} at ({:.4g}, {:.4g}, {:.4g}) um, t = {:.6g} ns: {}", body->name,
      s.points.id[p], s.points.position[0][p] * 1e6, s.points.position[1][p] * 1e6,
      s.points.position[2][p] * 1e6, s.time * 1e9, s.fault.cause));
}

}  // namespace coldspray::bodies
