#include "mpm/grid.hpp"

#include <algorithm>

namespace coldspray::mpm {

void GridFields::resize(std::size_t n) {
  mass.resize(n);
  for (auto* a : {&momentum, &force, &velocity, &velocity_change})
    for (auto& v : *a) v.resize(n);
  reached_by.resize(n);
  contact_slot.resize(n);
  clear();
}

void GridFields::clear() {
  std::fill(mass.begin(), mass.end(), 0.0);
  for (auto* a : {&momentum, &force})
    for (auto& v : *a) std::fill(v.begin(), v.end(), 0.0);
  std::fill(reached_by.begin(), reached_by.end(), kNoBody);
  std::fill(contact_slot.begin(), contact_slot.end(), -1);
}

}  // namespace coldspray::mpm
