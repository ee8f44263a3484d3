// Material points seeded on a regular lattice inside a shape, with surface flags.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/shape.hpp"

namespace coldspray::geometry {

// Lattice sites are origin + (i + 1/2) spacing along each axis, so a lattice whose origin is a
// grid node puts the same number of points in every cell when spacing divides the cell size.
// Axisymmetric lattices lie in the r-z plane (x = r >= 0, y = 0) with the first column at
// r = spacing/2; a point then stands for the ring of volume 2 pi r spacing^2.
struct Lattice {
  Vec3 origin = Vec3::Zero();
  double spacing = 0.0;
  bool axisymmetric = false;
};

// Bits of SeededPoints::outside: which face neighbours on the lattice lie outside the shape.
enum OutsideNeighbour : std::uint8_t {
  kMinusX = 1,
  kPlusX = 2,
  kMinusY = 4,
  kPlusY = 8,
  kMinusZ = 16,
  kPlusZ = 32,
};

struct SeededPoints {
  std::vector<Vec3> position;
  std::vector<double> volume;         // m^3 (3D cube, or axisymmetric ring)
  std::vector<std::uint8_t> outside;  // OutsideNeighbour bits; non-zero on the surface
};

// Seeds every lattice site inside `shape`. A point is on the surface when one of its face
// neighbours on the lattice (6 in 3D; 4 in r-z, the axis not counting as a boundary) is not
// inside the shape: the points bonding acts on (thesis §4.1.1, the set S). Which neighbours are
// outside tells the face (bottom: -z, top: +z, side: the others) for fixed and absorbing faces.
SeededPoints seed(const case_file::Shape& shape, const Lattice& lattice);

}  // namespace coldspray::geometry
