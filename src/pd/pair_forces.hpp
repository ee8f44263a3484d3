// The bond and control force densities of all points with each pair of neighbours visited once
// (PD paper eq 8 with Silling's control, pd/forces.hpp). The per-point sum (force_density)
// visits every bond twice, once from each end, and each visit reads the far end's A (eq 7) and
// second-order fit C, 384 bytes; here the pair (i, j), j > i, is visited from i, which adds its
// part to both ends, so those reads halve. Ghosts (indices past the real points) receive
// nothing: their sources get the mirrored pairs themselves.
//
// Determinism: the points are cut into blocks of consecutive indices, each (but the last) at
// least as long as the largest index distance of a pair, so that the pairs visited from block k
// write only blocks k and k + 1. The even blocks run in parallel, then the odd ones; within a
// block the pairs are visited in index order. Every point therefore receives its contributions
// in one fixed order, whatever the number of threads.
#pragma once

#include <cstddef>
#include <vector>

#include "pd/state.hpp"

namespace coldspray::pd {

// The first bond of each real point's family whose neighbour index exceeds the point's (the
// families are sorted), and the blocks' first points (the last entry the real count).
PairSchedule pair_schedule(const Families& fam, std::size_t real);

// s.pair_bonds and s.pair_control of every real point of the bodies the step advances
// (State::advancing): eq 8's bond force density and the control's, N/m^3, equal to
// force_density's bonds and control but for round-off.
void pair_forces(State& s);

}  // namespace coldspray::pd
