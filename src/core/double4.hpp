// Four doubles as one GCC vector: element-wise +, -, * with scalars broadcast, one AVX register
// where the build targets AVX2 (pairs of SSE registers elsewhere). The MPM step keeps tensor
// columns in it, the fourth lane unused, so that a node's share is a few vector multiply-adds
// instead of a dozen scalar ones.
#pragma once

#include <Eigen/Core>
#include <cstring>

namespace coldspray {

using Double4 = double __attribute__((vector_size(32)));
// Lane indices for __builtin_shuffle(a, Lanes4{i, j, k, l}): lanes i, j, k, l of a.
using Lanes4 = long __attribute__((vector_size(32)));

// One lane of a in all four (a register permute).
template <int k>
inline Double4 lane(Double4 a) {
  return __builtin_shuffle(a, Lanes4{k, k, k, k});
}

// An Eigen four-vector as one register.
inline Double4 as_lanes(const Eigen::Vector4d& v) {
  Double4 l;
  std::memcpy(&l, v.data(), sizeof l);
  return l;
}

}  // namespace coldspray
