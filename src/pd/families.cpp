#include "pd/families.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/interrupt.hpp"

namespace coldspray::pd {

namespace {

// One body's points binned into cubic cells of edge `cell`, counting sort by cell, so a point's
// neighbours are searched in the 27 cells around its own.
struct CellList {
  double cell = 0.0;
  std::array<double, 3> origin{};
  std::array<long, 3> cells{};
  std::vector<std::size_t> start;    // cell c's points are order[start[c] .. start[c + 1])
  std::vector<std::uint32_t> order;  // point indices, by cell, ascending within a cell

  long index(long i, long j, long k) const { return (k * cells[1] + j) * cells[0] + i; }
  long coordinate(double x, int d) const {
    return std::clamp(static_cast<long>(std::floor((x - origin[d]) / cell)), 0L, cells[d] - 1);
  }
};

// The points `members` (ascending) binned.
CellList bin(const std::vector<Eigen::Vector4d>& X, const std::vector<std::uint32_t>& members,
             double cell) {
  CellList list;
  list.cell = cell;
  for (int d = 0; d < 3; ++d) {
    double lo = X[members.front()][d], hi = lo;
    for (const std::uint32_t p : members) {
      lo = std::min(lo, X[p][d]);
      hi = std::max(hi, X[p][d]);
    }
    list.origin[d] = lo;
    list.cells[d] = static_cast<long>(std::floor((hi - lo) / cell)) + 1;
  }
  const std::size_t n = static_cast<std::size_t>(list.cells[0] * list.cells[1] * list.cells[2]);
  list.start.assign(n + 1, 0);
  std::vector<std::size_t> cell_of(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) {
    const std::uint32_t p = members[m];
    const long c = list.index(list.coordinate(X[p][0], 0), list.coordinate(X[p][1], 1),
                              list.coordinate(X[p][2], 2));
    cell_of[m] = static_cast<std::size_t>(c);
    ++list.start[c + 1];
  }
  for (std::size_t c = 0; c < n; ++c) list.start[c + 1] += list.start[c];
  list.order.resize(members.size());
  std::vector<std::size_t> cursor(list.start.begin(), list.start.end() - 1);
  for (std::size_t m = 0; m < members.size(); ++m) list.order[cursor[cell_of[m]]++] = members[m];
  return list;
}

}  // namespace

Families build_families(const Neighbours& N, const std::vector<bodies::BodyRange>& bodies,
                        const std::vector<double>& delta) {
  const std::vector<Eigen::Vector4d>& X = N.reference;
  if (N.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("peridynamics: more than 2^32 points");
  Families f;
  f.begin.assign(N.real + 1, 0);
  std::vector<std::uint32_t> found, members;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const bodies::BodyRange& body = bodies[b];
    const double h = body.spacing, reach = delta[b] + 0.5 * h;
    members.clear();
    for (std::size_t p = 0; p < N.size(); ++p)
      if (N.body[p] == b) members.push_back(static_cast<std::uint32_t>(p));
    const CellList list = bin(X, members, reach);
    for (std::size_t p = body.begin; p < body.end; ++p) {
      // Set-up only (the families are built once): the stop flag every 4096 points, a few
      // milliseconds of this loop.
      if (p % 4096 == 0) stop_set_up_if_interrupted("building the peridynamic families");
      found.clear();
      const long ci = list.coordinate(X[p][0], 0), cj = list.coordinate(X[p][1], 1),
                 ck = list.coordinate(X[p][2], 2);
      for (long k = std::max(ck - 1, 0L); k <= std::min(ck + 1, list.cells[2] - 1); ++k)
        for (long j = std::max(cj - 1, 0L); j <= std::min(cj + 1, list.cells[1] - 1); ++j)
          for (long i = std::max(ci - 1, 0L); i <= std::min(ci + 1, list.cells[0] - 1); ++i) {
            const long c = list.index(i, j, k);
            for (std::size_t s = list.start[c]; s < list.start[c + 1]; ++s) {
              const std::uint32_t q = list.order[s];
              if (q == p) continue;
              const double dx = X[q][0] - X[p][0], dy = X[q][1] - X[p][1], dz = X[q][2] - X[p][2];
              if (volume_fraction(std::sqrt(dx * dx + dy * dy + dz * dz), delta[b], h) > 0.0)
                found.push_back(q);
            }
          }
      std::sort(found.begin(), found.end());
      for (const std::uint32_t q : found) {
        const double dx = X[q][0] - X[p][0], dy = X[q][1] - X[p][1], dz = X[q][2] - X[p][2];
        const double beta = volume_fraction(std::sqrt(dx * dx + dy * dy + dz * dz), delta[b], h);
        f.neighbour.push_back(q);
        f.partial_volume.push_back(
            static_cast<std::uint16_t>(std::lround(beta * Families::kPartialVolumeUnit)));
      }
      f.begin[p + 1] = f.neighbour.size();
    }
  }
  return f;
}

}  // namespace coldspray::pd
