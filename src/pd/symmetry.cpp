#include "pd/symmetry.hpp"

#include <cmath>

#include "pd/tensor_field.hpp"

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
                   std::abs(N.reference[i][axis] - *s.symmetry_plane[axis]) < reach;
        if (!near) continue;
        s.ghosts.push_back({static_cast<std::uint32_t>(i), flips});
        Eigen::Vector4d X = N.reference[i];
        for (int d = 0; d < 2; ++d)
          if (flips >> d & 1) X[d] = 2.0 * *s.symmetry_plane[d] - X[d];
        N.reference.push_back(X);
        N.volume.push_back(N.volume[i]);
        N.body.push_back(N.body[i]);
      }
  }
  N.position.assign(N.size(), Eigen::Vector4d::Zero());
  N.velocity.assign(N.size(), Eigen::Vector4d::Zero());
}

void refresh_ghost_motion(State& s) {
  Neighbours& N = s.neighbours;
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t g = 0; g < s.ghosts.size(); ++g) {
    const Ghost& ghost = s.ghosts[g];
    const std::size_t j = N.real + g, i = ghost.source;
    N.position[j] = N.position[i];
    N.velocity[j] = N.velocity[i];
    for (int d = 0; d < 2; ++d)
      if (ghost.flips >> d & 1) {
        N.position[j][d] = 2.0 * *s.symmetry_plane[d] - N.position[i][d];
        N.velocity[j][d] = -N.velocity[i][d];
      }
  }
}

void refresh_ghost_tensors(State& s) {
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t g = 0; g < s.ghosts.size(); ++g) {
    const Ghost& ghost = s.ghosts[g];
    const Eigen::Matrix3d R = reflection(ghost.flips);
    const std::size_t j = s.neighbours.real + g, i = ghost.source;
    store_tensor(R * s.piola_over_shape[i].topRows<3>() * R, s.piola_over_shape, j);
    s.velocity_fit[j] = mirrored(s.velocity_fit[i], ghost.flips);
    store_tensor(R * s.flow_direction[i].topRows<3>() * R, s.flow_direction, j);
    s.flow_softening[j] = s.flow_softening[i];
  }
}

void refresh_ghost_slip_fits(State& s) {
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t g = 0; g < s.ghosts.size(); ++g)
    s.slip_fit[s.neighbours.real + g] = mirrored(s.slip_fit[s.ghosts[g].source], s.ghosts[g].flips);
}

void refresh_neighbours(State& s) {
  Neighbours& N = s.neighbours;
  const bodies::Points& P = s.points;
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < P.size(); ++i) {
    N.position[i] = {P.position[0][i], P.position[1][i], P.position[2][i], 0.0};
    N.velocity[i] = {P.velocity[0][i], P.velocity[1][i], P.velocity[2][i], 0.0};
  }
  refresh_ghost_motion(s);
}

}  // namespace coldspray::pd
