// The bounding box of a body's shape: read by the seeding (geometry/), and by the case's own size
// estimate (case/size_estimate.hpp), which may not reach up into geometry/.
#pragma once

#include "case/case.hpp"

namespace coldspray::case_file {

struct Bounds {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};

// The smallest axis-aligned box holding the shape.
Bounds bounding_box(const Shape& shape);

}  // namespace coldspray::case_file
