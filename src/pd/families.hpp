// The families of peridynamics (PD paper, "State-Based Peridynamic Theory"): every point's
// neighbours within its horizon delta in the reference configuration, among the points of its
// own body (bodies meet only through contact, pd/contact.hpp). Built once, stored compactly:
// a CSR of 32-bit neighbour indices with, per bond, the fraction of the neighbour's volume that
// lies inside the horizon; 8 bytes per bond.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bodies/bodies.hpp"
#include "pd/neighbours.hpp"

namespace coldspray::pd {

struct Families {
  std::vector<std::size_t> begin;        // point i's bonds are [begin[i], begin[i + 1])
  std::vector<std::uint32_t> neighbour;  // per bond: the neighbour's point index
  // Per bond: the partial-volume factor of the neighbour's cell, 1 well inside the horizon,
  // (delta + h/2 - |xi|) / h across its edge (the linear rule of Seleson, Comput. Methods Appl.
  // Mech. Engrg. 282 (2014); "PA-AC" without its area correction).
  std::vector<float> volume_fraction;

  std::size_t points() const { return begin.empty() ? 0 : begin.size() - 1; }
  std::size_t bonds() const { return neighbour.size(); }
};

// The partial-volume factor of a neighbour at reference distance r from a point whose horizon
// is delta, on a lattice of spacing h: 1 for r <= delta - h/2, 0 beyond delta + h/2, linear in
// between.
double volume_fraction(double r, double delta, double h);

// Families of the real points of `bodies`, among the points of N (real and ghost) of the same
// body in their reference positions, with horizon delta[b] for body b, found with a cell list of
// cells delta + h/2 wide; each point's neighbours in ascending index order. Throws
// std::length_error past 2^32 points.
Families build_families(const Neighbours& N, const std::vector<bodies::BodyRange>& bodies,
                        const std::vector<double>& delta);

}  // namespace coldspray::pd
