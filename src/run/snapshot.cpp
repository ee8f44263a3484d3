#include "run/snapshot.hpp"

#include <cmath>

#include "io/vtu.hpp"

namespace coldspray::run {

void write_snapshot(const mpm::State& s, const std::filesystem::path& path) {
  const mpm::Points& P = s.points;
  const std::size_t n = P.size();
  std::vector<std::int32_t> body(n);
  std::vector<double> von_mises(n), density(n);
  for (std::size_t p = 0; p < n; ++p) {
    using namespace mpm;
    body[p] = P.body[p];
    const double mean = (P.stress[kXX][p] + P.stress[kYY][p] + P.stress[kZZ][p]) / 3.0;
    const double sxx = P.stress[kXX][p] - mean, syy = P.stress[kYY][p] - mean,
                 szz = P.stress[kZZ][p] - mean;
    const double shear = P.stress[kXY][p] * P.stress[kXY][p] + P.stress[kYZ][p] * P.stress[kYZ][p] +
                         P.stress[kXZ][p] * P.stress[kXZ][p];
    von_mises[p] = std::sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2.0 * shear));
    density[p] = s.bodies[P.body[p]].material.density / P.J[p];
  }
  io::VtuPointCloud cloud(P.position);
  cloud.add_int("body", body);
  cloud.add_vector("velocity", P.velocity);
  cloud.add_scalar("eqps", P.eqps);
  cloud.add_scalar("temperature", P.temperature);
  cloud.add_scalar("pressure", P.pressure);
  cloud.add_scalar("von_mises", von_mises);
  cloud.add_scalar("density", density);
  cloud.add_byte("surface", P.surface);
  cloud.add_scalar("bond", P.bond);
  cloud.write(path);
}

}  // namespace coldspray::run
