// A deposit's size, held against what its patch and the size caps allow before its particles are
// placed (docs/deposit.md, "Bad input"): placing them and reading the case they make take time
// in proportion to their number, so an impossible count is refused first, at its key.
#pragma once

#include <vector>

#include "case/load.hpp"
#include "setups/deposit_file.hpp"

namespace coldspray::setups {

// InputError (exit 2) at the file's particles.count when the particles' sizes (the ones
// place_particles will draw) cannot fit the patch and the heights of their arrivals
// (studies/deposit_room.hpp), or at particles.count or patch, whichever seeds more, when the
// case would have more points than limits.max_points (`--set limits.max_points=N` as for the
// case): the estimate of the case's own check (case/size_limits.hpp), each particle's sphere and
// the substrate's box over the spacing cubed.
void check_deposit_size(const DepositFile& file, const std::vector<case_file::Override>& sets);

}  // namespace coldspray::setups
