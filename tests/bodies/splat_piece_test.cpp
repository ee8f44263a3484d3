// The piece of a body that hangs together (bodies/splat_piece.hpp), by hand: points on a line
// whose gaps are set either side of the link, kPieceLinkSpacings = 3 spacings.
#include "bodies/splat_piece.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace coldspray::bodies {
namespace {

// One body of points at x = xs (um), 1 um spacing, masses ms, after `offset` points of another
// body (at the origin) that the piece must not look at.
Points line(const std::vector<double>& xs, const std::vector<double>& ms, std::size_t offset,
            BodyRange& body) {
  Points P;
  P.resize(offset + xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    P.position[0][offset + i] = xs[i] * 1e-6;
    P.position[2][offset + i] = 0.5e-6 * static_cast<double>(i % 2);  // off the line a little
    P.mass[offset + i] = ms[i];
  }
  body.begin = offset, body.end = offset + xs.size();
  body.spacing = 1e-6;
  return P;
}

TEST(SplatPiece, LeavesOutADropBeyondTheLink) {
  BodyRange body;
  // Gaps 1, 1, 2.9 (sqrt(2.9^2 + 0.5^2) = 2.943 < 3 with the z offsets) join; the drop at 12 and
  // 13 um is 7 um from the rest.
  const Points P = line({0.0, 1.0, 2.0, 4.9, 12.0, 13.0}, {1, 1, 1, 1, 1, 1}, 3, body);
  EXPECT_EQ(splat_piece(P, body), (std::vector<char>{1, 1, 1, 1, 0, 0}));
}

TEST(SplatPiece, AGapJustOverTheLinkParts) {
  BodyRange body;
  // 3.0 along x and 0.5 across: 3.04 um > 3 um.
  const Points P = line({0.0, 1.0, 4.0}, {1, 1, 1}, 0, body);
  EXPECT_EQ(splat_piece(P, body), (std::vector<char>{1, 1, 0}));
}

TEST(SplatPiece, TheHeaviestPieceWinsAndATieGoesToTheLowestIndex) {
  BodyRange body;
  // Three light points against two heavy ones, 10 um apart: the heavy pair (mass 4 > 3).
  const Points P = line({0.0, 1.0, 2.0, 12.0, 13.0}, {1, 1, 1, 2, 2}, 0, body);
  EXPECT_EQ(splat_piece(P, body), (std::vector<char>{0, 0, 0, 1, 1}));
  const Points Q = line({0.0, 1.0, 12.0, 13.0}, {1, 1, 1, 1}, 0, body);
  EXPECT_EQ(splat_piece(Q, body), (std::vector<char>{1, 1, 0, 0}));
}

}  // namespace
}  // namespace coldspray::bodies
