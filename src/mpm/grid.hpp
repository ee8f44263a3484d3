// The background grid: a regular lattice of nodes, reset every step (thesis §3.4 step 12).
// In 3D it has nx * ny * nz nodes; in axisymmetric runs ny = 1 and x is the radius r >= 0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace coldspray::mpm {

struct GridLayout {
  std::array<double, 3> origin{};  // position of node (0, 0, 0), m
  double h = 0.0;                  // cell size, m
  std::array<int, 3> nodes{};      // node counts per axis
  bool axisymmetric = false;

  std::size_t node_count() const {
    return static_cast<std::size_t>(nodes[0]) * nodes[1] * nodes[2];
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(nodes[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(nodes[1]) * k);
  }
  double coordinate(int axis, int i) const { return origin[axis] + i * h; }
  // Upper end of the grid along an axis.
  double extent(int axis) const { return origin[axis] + (nodes[axis] - 1) * h; }
};

// What a node gathers from the points in steps 1-2 (and its momentum again in the re-map of
// step 8), side by side: a point's scatter to a node then touches one cache line, where one
// array per quantity made it seven.
struct alignas(64) NodeSums {
  double mass = 0.0;                 // kg
  std::array<double, 3> momentum{};  // kg m/s
  std::array<double, 3> force{};     // N
};

// Eq 3.32's nodal velocities p/m and the step's velocity change f dt/m, side by side for the
// grid-to-point phases, which read both at each node of a point's stencil.
struct NodeMotion {
  std::array<double, 3> velocity;         // m/s
  std::array<double, 3> velocity_change;  // m/s
};

// Heat conduction's nodal sums (mpm/heat_conduction.hpp): heat capacity sum N m C_p, J/K; the
// temperature (first the heat content sum N m C_p T, J, then divided by the capacity), K; the heat
// flowing into the node, W.
struct NodeHeat {
  double capacity = 0.0;
  double temperature = 0.0;
  double flow = 0.0;
};

// Nodal quantities summed over all bodies.
struct GridFields {
  std::vector<NodeSums> sums;
  // Which bodies reach a node this step: none, the one body that does, or two and more.
  static constexpr std::int32_t kNoBody = -1, kManyBodies = -2;
  std::vector<std::int32_t> reached_by;
  // Index of the node's slot in the contact storage, or -1 where only one body has mass.
  std::vector<std::int32_t> contact_slot;
  // Once per phase that reads them (mpm/phases.hpp: compute_nodal_velocities).
  std::vector<NodeMotion> motion;
  // Only with solver.heat_conduction; empty otherwise.
  std::vector<NodeHeat> heat;

  void resize(std::size_t n);
  void clear();  // zero the sums for a new step (no allocation); velocities follow from them
};

}  // namespace coldspray::mpm
