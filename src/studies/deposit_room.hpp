// Whether a deposit's particles can fit where place_particles puts them (docs/deposit.md,
// "Placement"), known from their sizes alone, before placing them: a count past this bound is
// refused at once, not after a search through every particle's draws.
#pragma once

#include <vector>

#include "studies/deposit_placement.hpp"

namespace coldspray::studies {

struct DepositRoom {
  double needed = 0.0;  // m^3: the particles' spheres grown by half the clearance
  double room = 0.0;    // m^3: the region those spheres lie in
  int most = 0;         // about how many spheres of their mean volume the region holds

  bool fits() const { return needed <= room; }
};

// Two particles placed are at least their radii and the clearance apart, so their spheres grown
// by half the clearance do not overlap. Each centre lies over the patch, at a height between half
// its diameter and its speed times the arrival window above that; so each grown sphere lies in
// that box grown by the largest grown radius. Disjoint spheres in a region fill at most its
// volume: past that no arrangement holds them, whatever the draws.
DepositRoom deposit_room(const DepositPlan& plan, const std::vector<double>& diameters);

}  // namespace coldspray::studies
