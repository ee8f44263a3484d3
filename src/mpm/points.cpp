#include "mpm/points.hpp"

namespace coldspray::mpm {

void Points::resize(std::size_t n) {
  for (auto* a : {&position, &velocity, &displacement, &half_width, &contact_normal})
    for (auto& v : *a) v.resize(n, 0.0);
  for (auto& v : stress) v.resize(n, 0.0);
  for (auto* v : {&mass, &volume0, &eqps, &eqps_rate, &return_slope, &temperature, &energy, &J,
                  &flow_stress, &shear_modulus, &sound_speed, &bulk_viscosity, &plastic_work,
                  &viscous_work, &contact_work, &initial_z, &bond})
    v->resize(n, 0.0);
  body.resize(n, 0);
  surface.resize(n, 0);
  touched.resize(n, 0);
  touching.resize(n, 0);
  bonded_to.resize(n, 0);
}

}  // namespace coldspray::mpm
