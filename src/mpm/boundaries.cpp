#include "mpm/boundaries.hpp"

namespace coldspray::mpm {

void apply_node_constraints(State& s, bool force_too) {
  GridFields& g = s.grid;
  const long nodes = static_cast<long>(s.layout.node_count());
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) {
    const std::uint8_t held = s.constraint[n];
    if (held == 0) continue;
    for (int d = 0; d < 3; ++d)
      if (held & (1u << d)) {
        g.sums[n].momentum[d] = 0.0;
        if (force_too) g.sums[n].force[d] = 0.0;
      }
  }
  ContactNodes& c = s.contact;
  for (std::size_t slot = 0; slot < c.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    const std::uint8_t held = s.constraint[c.node(sl)];
    if (held == 0) continue;
    for (int e = 0; e < c.body_count(sl); ++e)
      for (int d = 0; d < 3; ++d)
        if (held & (1u << d)) {
          c.momentum[d][ContactNodes::flat(sl, e)] = 0.0;
          if (force_too) c.force[d][ContactNodes::flat(sl, e)] = 0.0;
        }
  }
}

void apply_absorbing_dashpots(State& s) {
  Points& P = s.points;
  const long count = static_cast<long>(s.absorbing.size());
  const double inverse_dt = s.displacement_dt > 0.0 ? 1.0 / s.displacement_dt : 0.0;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) {
    AbsorbingPoint& a = s.absorbing[i];
    for (int d = 0; d < 3; ++d)
      s.external_force[d][a.point] =
          -a.damping[d] *
          (inverse_dt > 0.0 ? P.displacement[d][a.point] * inverse_dt : P.velocity[d][a.point]);
  }
}

void account_absorbed_work(State& s) {
  const Points& P = s.points;
  const long count = static_cast<long>(s.absorbing.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) {
    AbsorbingPoint& a = s.absorbing[i];
    for (int d = 0; d < 3; ++d)
      a.absorbed -= s.external_force[d][a.point] * P.displacement[d][a.point];
  }
}

}  // namespace coldspray::mpm
