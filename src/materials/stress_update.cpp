#include "materials/stress_update.hpp"

#include "materials/model_dispatch.hpp"
#include "materials/stress_update_kernel.hpp"

namespace coldspray::materials {

PointState initial_state(const Material& m, double temperature) {
  return visit_models(m, [&](const auto& models) { return initial_point(models, temperature); });
}

void update_stress(const Material& m, const StepKinematics& k, const UpdateOptions& opt,
                   PointState& state) {
  visit_models(m, [&](const auto& models) { update_point(models, k, opt, state); });
}

double wave_speed(const Material& m, const PointState& state) {
  return visit_models(m, [&](const auto& models) { return point_wave_speed(models, state); });
}

}  // namespace coldspray::materials
