// A snapshot of the material points for ParaView: body id, velocity, eqps, temperature,
// pressure, von Mises stress, density, the surface flag, the bond indicator and partner, and in
// peridynamics each point's neighbour count. In r-z runs the points lie in the x-z plane with
// x = r.
#pragma once

#include <filesystem>

#include "bodies/bodies.hpp"

namespace coldspray::run {

void write_snapshot(const bodies::Bodies& s, const std::filesystem::path& path);

}  // namespace coldspray::run
