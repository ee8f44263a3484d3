// A melting temperature independent of compression.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials::melt {

inline double temperature(const Constant& c, double /*eta*/) { return c.temperature; }

}  // namespace coldspray::materials::melt
