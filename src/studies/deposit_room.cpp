#include "studies/deposit_room.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace coldspray::studies {

// The bound is of volume alone (density 1), not the density a random placement reaches: adding
// equal spheres at random positions saturates at a volume fraction of about 0.38 in 3D and 0.547 in
// 2D (Torquato, Uche & Stillinger, Phys. Rev. E 74 (2006) 061308, random sequential addition),
// and place_particles gives up earlier still (kPlacementTries draws a particle). Those fractions
// hold for spheres of one size in unbounded space; a spread of sizes packs denser and the box's
// walls change them, so they are no bound here. Between them and this one, placement is left to
// find out, in at most kPlacementTries draws a particle.
DepositRoom deposit_room(const DepositPlan& plan, const std::vector<double>& diameters) {
  DepositRoom r;
  if (diameters.empty()) return r;
  double lowest = std::numeric_limits<double>::max(), highest = 0.0, grown = 0.0;
  for (const double d : diameters) {
    const double radius = 0.5 * (d + plan.clearance);
    r.needed += 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    grown = std::max(grown, radius);
    // The centre's height: its bottom speed * arrival above z = 0 (place_particles).
    lowest = std::min(lowest, 0.5 * d);
    highest = std::max(highest, 0.5 * d + plan.speed_of(d) * plan.arrival_window);
  }
  r.room = (plan.patch[0] + 2.0 * grown) * (plan.patch[1] + 2.0 * grown) *
           (highest - lowest + 2.0 * grown);
  const double mean = r.needed / static_cast<double>(diameters.size());
  r.most = static_cast<int>(std::min(std::floor(r.room / mean), 2e9));
  return r;
}

}  // namespace coldspray::studies
