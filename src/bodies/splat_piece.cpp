#include "bodies/splat_piece.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace coldspray::bodies {

namespace {

// Union-find over the body's points, by index from body.begin.
struct Pieces {
  std::vector<std::size_t> parent;
  explicit Pieces(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t root(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a), b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the lowest index is the root
  }
};

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return static_cast<std::size_t>(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
  }
};

}  // namespace

std::vector<char> splat_piece(const Points& P, const BodyRange& body) {
  const std::size_t n = body.end - body.begin;
  const double link = kPieceLinkSpacings * body.spacing;
  auto cell_of = [&](std::size_t i) {
    Cell c;
    for (int d = 0; d < 3; ++d)
      c[d] = static_cast<std::int64_t>(std::floor(P.position[d][body.begin + i] / link));
    return c;
  };
  // Points binned in cells of the link's size: a point's links lie in its cell's 27.
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells;
  for (std::size_t i = 0; i < n; ++i) cells[cell_of(i)].push_back(i);
  Pieces pieces(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Cell c = cell_of(i);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto near = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (near == cells.end()) continue;
          for (const std::size_t j : near->second) {
            if (j <= i) continue;
            double r2 = 0.0;
            for (int d = 0; d < 3; ++d) {
              const double dd = P.position[d][body.begin + i] - P.position[d][body.begin + j];
              r2 += dd * dd;
            }
            if (r2 < link * link) pieces.join(i, j);
          }
        }
  }
  std::vector<double> mass(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) mass[pieces.root(i)] += P.mass[body.begin + i];
  std::size_t heaviest = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (mass[i] > mass[heaviest]) heaviest = i;
  std::vector<char> in(n, 0);
  for (std::size_t i = 0; i < n; ++i) in[i] = pieces.root(i) == heaviest;
  return in;
}

}  // namespace coldspray::bodies
