// The material update of a body's points in batches, for whichever solver supplies the step's
// kinematics: points that the constitutive kernels take together (materials/
// stress_update_lanes.hpp), batches at fixed offsets from the body's first point, a short last
// batch padded with copies of its first point, so that a point's result depends neither on the
// threads nor on its neighbours. Both solvers call this, so both run the same stress update.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "bodies/bodies.hpp"
#include "bodies/material_state.hpp"
#include "materials/model_dispatch.hpp"
#include "materials/stress_update_lanes.hpp"

namespace coldspray::bodies {

// Batches of kBatchPoints points that a body's update is cut into.
inline std::size_t batch_count(const BodyRange& body) {
  return (body.end - body.begin + materials::kBatchPoints - 1) / materials::kBatchPoints;
}

// Updates batches [first_batch, end_batch) of `body` with the material's models: the step's
// kinematics of point p from kinematics_of(p), the new state handed to complete_point(p,
// kinematics, state), which stores it (bodies/material_state.hpp) after reading what it needs of
// the state before the step from P, and each point's longitudinal wave speed into
// P.sound_speed. Returns the largest c + |v| of
// the points.
template <class Models, class KinematicsOf, class CompletePoint>
double update_batches(const Models& models, Points& P, const BodyRange& body,
                      std::size_t first_batch, std::size_t end_batch, KinematicsOf&& kinematics_of,
                      CompletePoint&& complete_point) {
  using materials::kBatchPoints;
  double max_speed = 0.0;
  for (std::size_t batch = first_batch; batch < end_batch; ++batch) {
    const std::size_t first = body.begin + batch * kBatchPoints;
    const int count = static_cast<int>(std::min<std::size_t>(kBatchPoints, body.end - first));
    materials::StepKinematics k[kBatchPoints];
    materials::PointState state[kBatchPoints];
    for (int i = 0; i < kBatchPoints; ++i) {
      if (i < count) {
        k[i] = kinematics_of(first + i);
        state[i] = load_point_state(P, first + i);
      } else {
        k[i] = k[0];
        state[i] = state[0];
      }
    }
    materials::update_points(models, k, materials::UpdateOptions{}, state);
    for (int i = 0; i < count; ++i) complete_point(first + i, k[i], state[i]);
    // The wave speeds c and speeds |v|, the batch's square roots and divisions taken four at
    // once (the padding lanes repeat the first point).
    double modulus[kBatchPoints], J[kBatchPoints], v2[kBatchPoints];
    for (int i = 0; i < kBatchPoints; ++i) {
      const std::size_t p = first + (i < count ? i : 0);
      modulus[i] = materials::longitudinal_modulus(models, state[i]);
      J[i] = state[i].J;
      v2[i] = P.velocity[0][p] * P.velocity[0][p] + P.velocity[1][p] * P.velocity[1][p] +
              P.velocity[2][p] * P.velocity[2][p];
    }
    double c[kBatchPoints], speed[kBatchPoints];
    for (int i = 0; i < kBatchPoints; ++i) {
      c[i] = materials::wave_speed_of(modulus[i], models.material.density, J[i]);
      speed[i] = std::sqrt(v2[i]);
    }
    for (int i = 0; i < count; ++i) {
      P.sound_speed[first + i] = c[i];
      max_speed = std::max(max_speed, c[i] + speed[i]);
    }
  }
  return max_speed;
}

}  // namespace coldspray::bodies
