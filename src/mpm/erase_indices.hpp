// Removing elements by index from arrays whose other elements keep their order: the points that
// left the grid, from every per-point array (mpm/departures.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace coldspray::mpm {

// Removes v[i] for every i in `gone` (ascending, distinct, each < v.size()), the rest keeping
// their order: one pass that moves each run between two removed elements down. No reallocation.
template <class T>
void erase_indices(std::vector<T>& v, const std::vector<std::size_t>& gone) {
  if (gone.empty()) return;
  auto at = [&](std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
  auto out = at(gone[0]);
  for (std::size_t k = 0; k < gone.size(); ++k)
    out = std::move(at(gone[k] + 1), k + 1 < gone.size() ? at(gone[k + 1]) : v.end(), out);
  v.erase(out, v.end());
}

// Where index i (an element not in `gone`, or the end of a range) lands after erase_indices:
// i less the number of removed elements below it.
inline std::size_t index_after(std::size_t i, const std::vector<std::size_t>& gone) {
  return i - static_cast<std::size_t>(std::lower_bound(gone.begin(), gone.end(), i) - gone.begin());
}

}  // namespace coldspray::mpm
