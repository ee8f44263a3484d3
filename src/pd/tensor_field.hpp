// Reading and writing one point's 3x3 tensor (padded or not, pd/state.hpp), or its vector from
// per-component arrays.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "pd/state.hpp"

namespace coldspray::pd {

inline const Eigen::Matrix3d& tensor_at(const TensorField& T, std::size_t i) { return T[i]; }

inline void store_tensor(const Eigen::Matrix3d& M, TensorField& T, std::size_t i) { T[i] = M; }

inline void store_tensor(const Eigen::Matrix3d& M, PaddedTensorField& T, std::size_t i) {
  T[i].topRows<3>() = M;
  T[i].row(3).setZero();
}

inline Eigen::Vector3d vector_at(const std::array<std::vector<double>, 3>& v, std::size_t i) {
  return {v[0][i], v[1][i], v[2][i]};
}

}  // namespace coldspray::pd
