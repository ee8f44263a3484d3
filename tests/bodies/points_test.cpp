// Points::for_each_array is the one list of the per-point arrays: resize and the removal of points
// go through it, so an array missing from it would keep stale values or the wrong length.
#include "bodies/points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace coldspray::bodies {
namespace {

TEST(MpmPoints, ForEachArrayVisitsEveryArrayOnce) {
  Points P;
  std::size_t arrays = 0;
  P.for_each_array([&](auto&) { ++arrays; });
  // Points holds nothing but per-point std::vectors (alone or in std::arrays), all of one size.
  EXPECT_EQ(arrays * sizeof(std::vector<double>), sizeof(Points));
  std::vector<const void*> seen;
  P.for_each_array([&](auto& v) { seen.push_back(&v); });
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end());
}

TEST(MpmPoints, ResizeSizesEveryArray) {
  Points P;
  P.resize(7);
  P.for_each_array([](auto& v) { EXPECT_EQ(v.size(), 7u); });
}

}  // namespace
}  // namespace coldspray::bodies
