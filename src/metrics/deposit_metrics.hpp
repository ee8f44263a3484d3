// The measures of a deposit of several particles on a substrate (docs/deposit.md, "Measures"):
// the porosity and thickness of what stuck, from a voxelisation of the points' domains, and the
// deposition efficiency.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bodies/bodies.hpp"

namespace coldspray::metrics {

// Voxels over the patch, each marked by the material whose points' domains hold its centre.
struct DepositVoxels {
  static constexpr std::uint8_t kSubstrate = 1, kDeposit = 2;
  std::array<double, 3> origin{};  // corner of voxel (0, 0, 0), m
  double edge = 0.0;               // m
  std::array<int, 3> count{};      // voxels along x, y, z
  std::vector<std::uint8_t> mark;  // kSubstrate | kDeposit bits, x fastest

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(count[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(count[1]) * k);
  }
};

// Marks the voxels of edge `edge` over the patch [-patch/2, patch/2] in x and y whose centres lie
// in the domain (position +- half_width, the convected GIMP box, bodies/points.hpp) of a point of
// a deposit body (is_deposit[body]) no faster than `speed_limit` (jets in flight are not the
// deposit, thesis §5.2.2's filter) or of the substrate body. Along z they run from the substrate's
// top layer's lowest point (the crater's bottom; its top layer: the points that started within a
// spacing of surface_z) to the deposit's highest.
DepositVoxels voxelise_deposit(const bodies::Bodies& s, const std::vector<bool>& is_deposit,
                               std::size_t substrate, std::array<double, 2> patch, double edge,
                               double speed_limit, double surface_z);

struct DepositShape {
  // In each column of voxels that holds deposit, its envelope runs from above the highest
  // substrate voxel under the column's lowest deposit voxel (from the bottom if there is none)
  // up to its highest deposit voxel; the voids are the envelope's unmarked voxels. Porosity is
  // voids over envelope voxels summed over the columns (0 without deposit): the pores inside the
  // deposit and between it and the substrate, open or closed, as a cross-section would show them.
  double porosity = 0.0;
  // The deposit's top above surface_z (the substrate's top face at t = 0), averaged over all the
  // patch's columns (0 where none), and its highest, m.
  double mean_thickness = 0.0;
  double max_thickness = 0.0;
  double coverage = 0.0;  // fraction of the patch's columns that hold deposit
  // Per column (x fastest, columns[0] x columns[1]), the deposit's top above surface_z, m; 0
  // where there is none.
  std::array<int, 2> columns{};
  std::vector<double> thickness;
};

DepositShape deposit_shape(const DepositVoxels& v, double surface_z);

// Mass of the particles that bonded over the mass of all particles sprayed, at t = 0
// (masses of the whole particles, their departed points included).
double deposition_efficiency(const std::vector<double>& sprayed_mass,
                             const std::vector<bool>& bonded);

}  // namespace coldspray::metrics
