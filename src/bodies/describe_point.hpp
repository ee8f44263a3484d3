// How a fault report names a point: its body, id, position and the time.
#pragma once

#include <cstddef>
#include <string>

#include "bodies/bodies.hpp"

namespace coldspray::bodies {

// "body 'NAME', point ID at (x, y, z) um, t = T ns" for the point at index p, ID being its index
// at t = 0.
std::string describe_point(const Bodies& s, std::size_t p);

}  // namespace coldspray::bodies
