#include "bodies/points.hpp"

namespace coldspray::bodies {

void Points::resize(std::size_t n) {
  for_each_array([n](auto& v) { v.resize(n, 0); });
}

}  // namespace coldspray::bodies
