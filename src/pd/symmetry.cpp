#include "pd/symmetry.hpp"

#include <cmath>

namespace coldspray::pd {

namespace {

// R = diag(+-1, +-1, 1) of a ghost's flips.
Eigen::Matrix3d reflection(std::uint8_t flips) {
  return Eigen::Vector3d((flips & 1) ? -1.0 : 1.0, (flips & 2) ? -1.0 : 1.0, 1.0).asDiagonal();
}

}  // namespace

void add_ghosts(State& s) {
  Neighbours& N = s.neighbours;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const bodies::BodyRange& body = s.bodies[b];
    const double reach = s.body_bonds[b].horizon + 0.5 * body.spacing;
    for (std::uint8_t flips = 1; flips <= 3; ++flips)
      for (std::size_t i = body.begin; i < body.end; ++i) {
        bool near = true;
        for (int axis = 0; axis < 2; ++axis)
          if (flips >> axis & 1)
            near = near && s.symmetry_plane[axis] &&
                   std::abs(N.reference[axis][i] - *s.symmetry_plane[axis]) < reach;
        if (!near) continue;
        s.ghosts.push_back({static_cast<std::uint32_t>(i), flips});
        for (int d = 0; d < 3; ++d) {
          const bool flipped = d < 2 && (flips >> d & 1);
          const double x = N.reference[d][i];
          N.reference[d].push_back(flipped ? 2.0 * *s.symmetry_plane[d] - x : x);
        }
        N.volume.push_back(N.volume[i]);
        N.body.push_back(N.body[i]);
      }
  }
  for (int d = 0; d < 3; ++d) {
    N.position[d].resize(N.size());
    N.velocity[d].resize(N.size());
  }
}

void refresh_ghost_motion(State& s) {
  Neighbours& N = s.neighbours;
#pragma omp parallel for schedule(static)
  for (std::size_t g = 0; g < s.ghosts.size(); ++g) {
    const Ghost& ghost = s.ghosts[g];
    const std::size_t j = N.real + g, i = ghost.source;
    for (int d = 0; d < 3; ++d) {
      const bool flipped = d < 2 && (ghost.flips >> d & 1);
      N.position[d][j] = flipped ? 2.0 * *s.symmetry_plane[d] - N.position[d][i] : N.position[d][i];
      N.velocity[d][j] = flipped ? -N.velocity[d][i] : N.velocity[d][i];
    }
  }
}

void refresh_ghost_tensors(State& s) {
#pragma omp parallel for schedule(static)
  for (std::size_t g = 0; g < s.ghosts.size(); ++g) {
    const Ghost& ghost = s.ghosts[g];
    const Eigen::Matrix3d R = reflection(ghost.flips);
    const std::size_t j = s.neighbours.real + g, i = ghost.source;
    s.piola_over_shape[j] = R * s.piola_over_shape[i] * R;
    s.quadratic_fit[j] = mirrored(s.quadratic_fit[i], ghost.flips);
  }
}

void refresh_neighbours(State& s) {
  Neighbours& N = s.neighbours;
  const bodies::Points& P = s.points;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      N.position[d][i] = P.position[d][i];
      N.velocity[d][i] = P.velocity[d][i];
    }
  refresh_ghost_motion(s);
}

}  // namespace coldspray::pd
