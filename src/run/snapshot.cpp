#include "run/snapshot.hpp"

#include "bodies/material_state.hpp"
#include "io/vtu.hpp"
#include "materials/symmetric_tensor.hpp"

namespace coldspray::run {

void write_snapshot(const bodies::Bodies& s, const std::filesystem::path& path) {
  const bodies::Points& P = s.points;
  const std::size_t n = P.size();
  std::vector<std::int32_t> body(n), bonded_to(n);
  std::vector<double> pressure(n), von_mises(n), density(n), plastic_work(n);
  for (std::size_t p = 0; p < n; ++p) {
    body[p] = P.body[p];
    bonded_to[p] = static_cast<std::int32_t>(P.bonded_to[p]) - 1;  // -1: not bonded
    const materials::SymmetricTensor sigma = bodies::stress_at(P, p);
    pressure[p] = materials::mean_pressure(sigma);
    von_mises[p] = materials::von_mises_stress(sigma);
    density[p] = s.bodies[P.body[p]].material.density / P.J[p];
    plastic_work[p] = P.plastic_work[p] / P.volume0[p];
  }
  io::VtuPointCloud cloud(P.position);
  cloud.add_int("body", body);
  cloud.add_vector("velocity", P.velocity);
  cloud.add_scalar("eqps", P.eqps);
  cloud.add_scalar("temperature", P.temperature);
  cloud.add_scalar("pressure", pressure);
  cloud.add_scalar("von_mises", von_mises);
  cloud.add_scalar("density", density);
  cloud.add_scalar("plastic_work", plastic_work);  // per reference volume, J/m^3
  cloud.add_byte("surface", P.surface);
  cloud.add_scalar("bond", P.bond);
  cloud.add_int("bonded_to", bonded_to);
  cloud.add_scalar("bond_damage", P.bond_damage);
  // The point's domain, m: what a section draws of it (a coarsened point stands for a block).
  cloud.add_vector("half_width", P.half_width);
  if (!s.family_size.empty()) {
    const std::vector<std::int32_t> neighbours(s.family_size.begin(), s.family_size.end());
    cloud.add_int("neighbours", neighbours);
  }
  cloud.write(path);
}

}  // namespace coldspray::run
