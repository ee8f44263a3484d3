#include <fmt/format.h>

#include <algorithm>

#include "bodies/bodies.hpp"
#include "bodies/describe_point.hpp"
#include "core/error.hpp"

namespace coldspray::bodies {

void record_fault(Fault& fault, std::size_t p, const char* cause) noexcept {
#pragma omp critical(coldspray_fault)
  if (p < fault.point) {
    fault.point = p;
    fault.cause = cause;
  }
}

void raise_recorded_fault(const Bodies& s) {
  if (s.fault.point == std::numeric_limits<std::size_t>::max()) return;
  throw RunFault(fmt::format("{}: {}", describe_point(s, s.fault.point), s.fault.cause));
}

}  // namespace coldspray::bodies
