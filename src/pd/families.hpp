// The families of peridynamics (PD paper, "State-Based Peridynamic Theory"): every point's
// neighbours within its horizon delta in the reference configuration, among the points of its
// own body (bodies meet only through contact, pd/contact.hpp). Built once, stored compactly:
// a CSR of 32-bit neighbour indices with, per bond, the fraction of the neighbour's volume that
// lies inside the horizon in 16 bits; 6 bytes per bond.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "pd/neighbours.hpp"

namespace coldspray::pd {

struct Families {
  std::vector<std::size_t> begin;        // point i's bonds are [begin[i], begin[i + 1])
  std::vector<std::uint32_t> neighbour;  // per bond: the neighbour's point index
  // Per bond: the partial-volume factor beta (volume_fraction below) in units of 2^-15, to
  // within 1.5e-5 of a neighbour's volume (the rule itself is a first-order estimate of the
  // overlap of a cell and a sphere); 1, 1/2 and 1/4 are exact. Equal lengths give equal factors,
  // so a family that is symmetric stays so.
  std::vector<std::uint16_t> partial_volume;
  static constexpr double kPartialVolumeUnit = 32768.0;

  double volume_fraction(std::size_t bond) const {
    return static_cast<double>(partial_volume[bond]) * (1.0 / kPartialVolumeUnit);
  }

  std::size_t points() const { return begin.empty() ? 0 : begin.size() - 1; }
  std::size_t bonds() const { return neighbour.size(); }
};

// The partial-volume factor of a neighbour at reference distance r from a point whose horizon
// is delta, on a lattice of spacing h: 1 for r <= delta - h/2, 0 beyond delta + h/2, linear in
// between (the linear rule of Seleson, Comput. Methods Appl. Mech. Engrg. 282 (2014); "PA-AC"
// without its area correction).
inline double volume_fraction(double r, double delta, double h) {
  return std::clamp((delta + 0.5 * h - r) / h, 0.0, 1.0);
}

// What a bond's weight omega beta V_j needs of its body besides the families: the influence
// function omega and the horizon delta.
struct BondWeights {
  case_file::Influence influence = case_file::Influence::Constant;
  double delta = 0.0;  // m
};

// Families of the real points of `bodies`, among the points of N (real and ghost) of the same
// body in their reference positions, with horizon delta[b] for body b, found with a cell list of
// cells delta + h/2 wide; each point's neighbours in ascending index order. Throws
// std::length_error past 2^32 points, Interrupted at SIGINT or SIGTERM (core/interrupt.hpp).
Families build_families(const Neighbours& N, const std::vector<bodies::BodyRange>& bodies,
                        const std::vector<double>& delta);

}  // namespace coldspray::pd
