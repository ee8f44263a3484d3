#include "mpm/grid.hpp"

#include <algorithm>

namespace coldspray::mpm {

void GridFields::resize(std::size_t n) {
  sums.resize(n);
  motion.resize(n);
  reached_by.resize(n);
  contact_slot.resize(n);
  clear();
}

void GridFields::clear() {
  std::fill(sums.begin(), sums.end(), NodeSums{});
  std::fill(reached_by.begin(), reached_by.end(), kNoBody);
  std::fill(contact_slot.begin(), contact_slot.end(), -1);
}

}  // namespace coldspray::mpm
