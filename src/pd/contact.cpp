#include "pd/contact.hpp"

#include <algorithm>
#include <cmath>

#include "pd/laws/interface_bonds.hpp"

namespace coldspray::pd {

bool ContactList::stale(const Neighbours& P) const {
  const double limit = 0.25 * skin * skin;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if ((P.position[p] - built_at[p]).squaredNorm() > limit) return true;
  }
  return false;
}

void ContactList::build(const Neighbours& P, double reach) {
  const std::size_t n = P.size();
  if (remembers_stretch) {
    previous_begin.swap(begin);
    previous_other.swap(other);
    previous_largest.swap(largest_stretch);
  }
  built_at = P.position;
  ++builds;
  // Cells `reach` wide over the points' bounding box.
  double lo[3], hi[3];
  long cells[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = hi[d] = P.position[0][d];
    for (const Eigen::Vector4d& y : P.position) {
      lo[d] = std::min(lo[d], y[d]);
      hi[d] = std::max(hi[d], y[d]);
    }
    cells[d] = static_cast<long>(std::floor((hi[d] - lo[d]) / reach)) + 1;
  }
  auto coordinate = [&](double x, int d) {
    return std::clamp(static_cast<long>(std::floor((x - lo[d]) / reach)), 0L, cells[d] - 1);
  };
  auto index = [&](long i, long j, long k) { return (k * cells[1] + j) * cells[0] + i; };
  const std::size_t total = static_cast<std::size_t>(cells[0] * cells[1] * cells[2]);
  cell_start.assign(total + 1, 0);
  cell_of.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    cell_of[p] = static_cast<std::uint32_t>(index(coordinate(P.position[p][0], 0),
                                                  coordinate(P.position[p][1], 1),
                                                  coordinate(P.position[p][2], 2)));
    ++cell_start[cell_of[p] + 1];
  }
  for (std::size_t c = 0; c < total; ++c) cell_start[c + 1] += cell_start[c];
  cell_order.resize(n);
  cell_cursor.assign(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t p = 0; p < n; ++p)
    cell_order[cell_cursor[cell_of[p]]++] = static_cast<std::uint32_t>(p);
  begin.assign(P.real + 1, 0);
  other.clear();
  const double reach2 = reach * reach;
  for (std::size_t p = 0; p < P.real; ++p) {
    const long c[3] = {coordinate(P.position[p][0], 0), coordinate(P.position[p][1], 1),
                       coordinate(P.position[p][2], 2)};
    const std::size_t first = other.size();
    for (long k = std::max(c[2] - 1, 0L); k <= std::min(c[2] + 1, cells[2] - 1); ++k)
      for (long j = std::max(c[1] - 1, 0L); j <= std::min(c[1] + 1, cells[1] - 1); ++j)
        for (long i = std::max(c[0] - 1, 0L); i <= std::min(c[0] + 1, cells[0] - 1); ++i) {
          const long cell = index(i, j, k);
          for (std::size_t s = cell_start[cell]; s < cell_start[cell + 1]; ++s) {
            const std::uint32_t q = cell_order[s];
            if (P.body[q] == P.body[p]) continue;
            if ((P.position[q] - P.position[p]).squaredNorm() <= reach2) other.push_back(q);
          }
        }
    std::sort(other.begin() + static_cast<long>(first), other.end());
    begin[p + 1] = other.size();
  }
  if (remembers_stretch) carry_over_largest_stretch();
}

// Both lists of a point are sorted: one merge pass finds the pairs they share.
void ContactList::carry_over_largest_stretch() {
  largest_stretch.assign(other.size(), kUnbonded);
  if (previous_begin.empty()) return;
  for (std::size_t p = 0; p + 1 < begin.size(); ++p) {
    std::size_t old = previous_begin[p];
    for (std::size_t c = begin[p]; c < begin[p + 1]; ++c) {
      while (old < previous_begin[p + 1] && previous_other[old] < other[c]) ++old;
      if (old < previous_begin[p + 1] && previous_other[old] == other[c])
        largest_stretch[c] = previous_largest[old];
    }
  }
}

}  // namespace coldspray::pd
