// The points that families and contacts reach: the real points, then the ghosts, the mirror
// images of real points across the symmetry planes (pd/symmetry.hpp). Indices below the real
// count are the points' own; the arrays are refreshed from the points every step. Vectors are
// stored per point, padded to four doubles (x, y, z, 0): the bond loops read a neighbour's with
// one load.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace coldspray::pd {

struct Neighbours {
  std::size_t real = 0;                    // the real points: [0, real)
  std::vector<Eigen::Vector4d> reference;  // X, m
  std::vector<Eigen::Vector4d> position;   // y, m
  std::vector<Eigen::Vector4d> velocity;   // v, m/s
  std::vector<double> volume;              // V0, m^3
  std::vector<std::uint16_t> body;

  std::size_t size() const { return volume.size(); }
};

}  // namespace coldspray::pd
