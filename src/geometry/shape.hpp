// The body shapes a case file describes, their inside tests and their bounding boxes: read by the
// seeding (geometry/seeding.hpp) and by the case's own checks and size estimate (case/), which
// hold the shapes in their bodies.
#pragma once

#include <Eigen/Core>
#include <variant>

namespace coldspray::geometry {

using Vec3 = Eigen::Vector3d;

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;

  friend bool operator==(const Sphere&, const Sphere&) = default;
};
// Axis along z, from base_center up by height.
struct Cylinder {
  Vec3 base_center = Vec3::Zero();
  double radius = 0.0;
  double height = 0.0;

  friend bool operator==(const Cylinder&, const Cylinder&) = default;
};
struct Box {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();

  friend bool operator==(const Box&, const Box&) = default;
};
using Shape = std::variant<Sphere, Cylinder, Box>;

struct Bounds {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};

// True if x lies inside the shape or on its boundary.
bool contains(const Shape& shape, const Vec3& x);

// True if the shape and the axis-aligned box share a point (exact for the three shapes: the
// point of the box nearest the sphere's centre, or the cylinder's axis, within the radius).
bool meets(const Shape& shape, const Bounds& box);

// The smallest axis-aligned box holding the shape.
Bounds bounding_box(const Shape& shape);

}  // namespace coldspray::geometry
