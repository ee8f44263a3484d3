// Reading and writing one point's 3x3 tensor or vector in the state's per-component arrays.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "pd/state.hpp"

namespace coldspray::pd {

inline Eigen::Matrix3d tensor_at(const TensorField& T, std::size_t i) {
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) = T[3 * r + c][i];
  return M;
}

inline void store_tensor(const Eigen::Matrix3d& M, TensorField& T, std::size_t i) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) T[3 * r + c][i] = M(r, c);
}

inline Eigen::Vector3d vector_at(const std::array<std::vector<double>, 3>& v, std::size_t i) {
  return {v[0][i], v[1][i], v[2][i]};
}

}  // namespace coldspray::pd
