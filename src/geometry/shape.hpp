// Inside tests and bounding boxes of the body shapes a case file describes.
#pragma once

#include "case/case.hpp"

namespace coldspray::geometry {

using case_file::Vec3;

// True if x lies inside the shape or on its boundary.
bool contains(const case_file::Shape& shape, const Vec3& x);

struct Bounds {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};

// The smallest axis-aligned box holding the shape.
Bounds bounding_box(const case_file::Shape& shape);

}  // namespace coldspray::geometry
