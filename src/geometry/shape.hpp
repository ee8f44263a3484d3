// Inside tests and bounding boxes of the body shapes a case file describes.
#pragma once

#include "case/case.hpp"
#include "case/shape_bounds.hpp"

namespace coldspray::geometry {

using case_file::Vec3;

// True if x lies inside the shape or on its boundary.
bool contains(const case_file::Shape& shape, const Vec3& x);

// True if the shape and the axis-aligned box share a point (exact for the three shapes: the
// point of the box nearest the sphere's centre, or the cylinder's axis, within the radius).
bool meets(const case_file::Shape& shape, const case_file::Bounds& box);

// The smallest axis-aligned box holding the shape (case/shape_bounds.hpp).
using case_file::bounding_box;
using case_file::Bounds;

}  // namespace coldspray::geometry
