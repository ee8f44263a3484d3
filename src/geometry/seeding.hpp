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
  std::vector<double> size;           // edge of the point's cube (square in r-z), m
  std::vector<std::uint8_t> outside;  // OutsideNeighbour bits; non-zero on the surface

  // Adds the lattice site x of spacing s (SeededPoints::outside from its face neighbours).
  void add_site(const Shape& shape, const Vec3& x, double s, bool axisymmetric);
  // Adds a point standing for the whole cube (square in r-z) of edge b centred at x, inside
  // the shape and off its surface.
  void add_block(const Vec3& x, double b, bool axisymmetric);
};

// Seeds every lattice site inside `shape`. A point is on the surface when one of its face
// neighbours on the lattice (6 in 3D; 4 in r-z, the axis not counting as a boundary) is not
// inside the shape: the points bonding acts on (thesis §4.1.1, the set S). Which neighbours are
// outside tells the face (bottom: -z, top: +z, side: the others) for fixed and absorbing faces.
// Interrupted at SIGINT or SIGTERM (core/interrupt.hpp), read once a row of sites.
SeededPoints seed(const Shape& shape, const Lattice& lattice);

// Seeds the same lattice, but where a cube of 2^l x 2^l (x 2^l) sites, l <= levels, lies inside
// the shape, off its surface by a spacing, and farther than its own edge from the region
// `fine`, one point stands for the cube (docs/mpm.md, "Coarsened seeding"). The points' volumes
// add up to those of seed()'s, and the surface points are seed()'s.
SeededPoints seed_coarsened(const Shape& shape, const Lattice& lattice, int levels,
                            const Shape& fine);

}  // namespace coldspray::geometry
