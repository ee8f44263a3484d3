// Contact between bodies in peridynamics: the pairs of points of different bodies that a contact
// law (pd/laws/registry.hpp) acts on. By default the law is the short-range repulsion (Silling and
// Askari 2005, §"short-range forces"; Parks et al., Comput. Phys. Commun. 179 (2008) 777, as
// LAMMPS's PERI package implements it, pd/laws/repulsive.hpp): a point pair closer than the
// contact distance d pushes apart with force density
//   f = k_c c (d - r) / delta V_j  along the line between them,
// c = 18 K / (pi delta^4) the bond micromodulus, d = min(1.35 h, 0.9 |X_i - X_j|) by default:
// 1.35 spacings keeps points of one body out of the holes of another's lattice when it is
// stretched (its largest hole, at a cube's centre, is 0.87 h from the corners at rest), and 0.9
// of the initial distance lets bodies start closer than that without a push. The pairs are found in
// the current configuration with a cell list, kept with a skin and rebuilt once some point has
// moved half the skin since the last build. The PD paper's contact models 1
// (pd/laws/lennard_jones.hpp) and 2 (pd/laws/interface_bonds.hpp) are other force laws on these
// same pairs; model 2's bonds keep their largest stretch beside the list, carried over when it is
// rebuilt.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pd/neighbours.hpp"

namespace coldspray::pd {

struct ContactList {
  double skin = 0.0;                      // m
  std::vector<std::size_t> begin;         // point i's candidates: [begin[i], begin[i + 1])
  std::vector<std::uint32_t> other;       // candidate points of other bodies, ascending
  std::vector<Eigen::Vector4d> built_at;  // the positions at the last build, m
  // Per candidate, contact model 2's largest stretch since its bond formed (kUnbonded if none);
  // kept, and carried over by build(), only when `remembers_stretch`.
  bool remembers_stretch = false;
  std::vector<double> largest_stretch;
  // Scratch of the builds, kept so that rebuilding allocates only when the list grows.
  std::vector<std::size_t> cell_start, cell_cursor;
  std::vector<std::uint32_t> cell_order, cell_of;
  std::vector<std::size_t> previous_begin;
  std::vector<std::uint32_t> previous_other;
  std::vector<double> previous_largest;
  long builds = 0;

  // Whether some point (real or ghost) has moved more than half the skin since the last build.
  bool stale(const Neighbours& N) const;
  // Finds, for every real point, the points (real or ghost) of other bodies within reach = max
  // contact distance + skin (a cell list of cells `reach` wide over all of them). A pair that was
  // a candidate before keeps its largest stretch; a new one starts unbonded. The reach must cover
  // every bond's break distance, so that no bond is dropped.
  void build(const Neighbours& N, double reach);

 private:
  void carry_over_largest_stretch();
};

}  // namespace coldspray::pd
