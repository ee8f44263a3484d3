#include "mpm/grid.hpp"

namespace coldspray::mpm {

void GridFields::resize(std::size_t n) {
  sums.resize(n);
  motion.resize(n);
  reached_by.resize(n);
  contact_slot.resize(n);
  clear();
}

void GridFields::clear() {
  // In parallel: a few MB a step in 3D, which one thread writes in about half a millisecond.
  const long n = static_cast<long>(sums.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    sums[i] = NodeSums{};
    reached_by[i] = kNoBody;
    contact_slot[i] = -1;
  }
}

}  // namespace coldspray::mpm
