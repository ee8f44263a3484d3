// The case of `coldspray deposit` (docs/deposit.md): the placed particles as spheres above a
// box substrate under the patch, in one 3D MPM run with bonding, as YAML text that goes through
// the case reader and its checks like any case file.
#pragma once

#include <string>
#include <vector>

#include "geometry/shape.hpp"
#include "setups/deposit_file.hpp"
#include "setups/impact_case.hpp"

namespace coldspray::setups {

// The file's particles placed (studies::place_particles), or InputError at its patch when one
// found no place.
studies::Placement deposit_placement(const DepositFile& file);

// The particles' body names in arrival order: p1..pN, zero-padded to N's digits (p01..p10).
std::vector<std::string> particle_names(int count);

// The substrate's box: the patch and the file's margin on each side, `thickness` deep below its
// top face z = 0.
geometry::Box substrate_box(const DepositFile& file);

// The substrate's top face is z = 0; it spans the patch and the file's margin on each side.
// Bodies: the particles in arrival order, then the substrate (the highest body, as the thesis'
// multi-particle rule has it, §5.2.3). Runs to the last arrival plus the file's settle time.
GeneratedCase deposit_case(const DepositFile& file, const studies::Placement& placement);

}  // namespace coldspray::setups
