// Four doubles as one GCC vector: element-wise +, -, * with scalars broadcast, one AVX register
// where the build targets AVX2 (pairs of SSE registers elsewhere). The MPM step keeps tensor
// columns in it, the fourth lane unused, so that a node's share is a few vector multiply-adds
// instead of a dozen scalar ones.
#pragma once

namespace coldspray {

using Double4 = double __attribute__((vector_size(32)));

}  // namespace coldspray
