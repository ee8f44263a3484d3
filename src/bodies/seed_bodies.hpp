// Turning a case's bodies into points, the same for every solver: each body's shape seeded on
// its lattice (geometry/seeding.hpp), checked for overlaps, then laid out body after body in
// bodies::Points with the initial material state, and the points of absorbing faces found.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "geometry/seeding.hpp"

namespace coldspray::bodies {

struct SeededBody {
  geometry::SeededPoints points;
  double spacing = 0.0;
  case_file::Vec3 min, max;  // bounds of the points' domains (position +- spacing/2)
  std::array<std::optional<double>, 2> mirror_plane;  // see BodyRange::mirror_plane

  // min and max from the points.
  void bound();
};

// A plane a symmetric model is cut at: the points on its far side are removed, those with
// x[axis] < position if keep_above, else those with x[axis] > position.
struct CutPlane {
  int axis = 0;
  double position = 0.0;
  bool keep_above = true;
};

// Seeds every body of the case; throws InputError for a body with no points or bodies that
// overlap at t = 0, Interrupted at SIGINT or SIGTERM (core/interrupt.hpp).
std::vector<SeededBody> seed_bodies(const case_file::Case& c);

// Cuts the seeded bodies at the planes, setting a body's mirror plane (x and y planes) where it
// was cut. Throws InputError for a body with no points left; `planes_name` names the planes in
// that message.
void cut_at_planes(const case_file::Case& c, const std::vector<CutPlane>& planes,
                   const char* planes_name, std::vector<SeededBody>& seeded);

// Fills s.geometry, s.points, s.bodies, s.absorbing, s.contact_impulse and s.impact_metrics
// from the case and its seeded bodies (which a solver may have cut at its symmetry planes,
// setting their mirror planes), and s.max_signal_speed at t = 0.
void lay_out_bodies(const case_file::Case& c, const std::vector<SeededBody>& seeded, Bodies& s);

// OutsideNeighbour bits (geometry/seeding.hpp) that make a point part of the named faces.
std::uint8_t faces_bits(const std::vector<case_file::BodyFace>& faces);

}  // namespace coldspray::bodies
