// A point on a body's impact axis, the line along z through its centroid: the mass-weighted
// centroid, moved onto the planes the body was cut at (a symmetry plane of a quarter model; r = 0
// in r-z), where the whole body's centroid lies. The pull-off's grip and interface map measure
// radii from it.
#pragma once

#include <Eigen/Core>

#include "bodies/bodies.hpp"

namespace coldspray::bodies {

inline Eigen::Vector3d axis_point(const Points& P, const BodyRange& body) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double mass = 0.0;
  for (std::size_t i = body.begin; i < body.end; ++i) {
    for (int d = 0; d < 3; ++d) centroid[d] += P.mass[i] * P.position[d][i];
    mass += P.mass[i];
  }
  centroid /= mass;
  for (int d = 0; d < 2; ++d)
    if (body.mirror_plane[d]) centroid[d] = *body.mirror_plane[d];
  return centroid;
}

}  // namespace coldspray::bodies
