#include "materials/flow_stress.hpp"

#include "materials/model_dispatch.hpp"

namespace coldspray::materials {

double flow_stress(const Material& m, double eqps, double eqps_rate, double temperature,
                   double density) {
  return visit_models(m, [&](const auto& models) {
    const double G = models.shear_modulus_at(temperature);
    const double Tm = models.melt_temperature_at(density);
    return models.flow_stress_at(eqps, eqps_rate, {temperature, density, G, Tm});
  });
}

double shear_modulus_at(const Material& m, double temperature, double /*density*/) {
  return visit_models(m, [&](const auto& models) { return models.shear_modulus_at(temperature); });
}

double melt_temperature(const Material& m, double density) {
  return visit_models(m, [&](const auto& models) { return models.melt_temperature_at(density); });
}

}  // namespace coldspray::materials
