#include "metrics/energy.hpp"

namespace coldspray::metrics {

EnergyBudget energy_budget(const bodies::Bodies& s) {
  const bodies::Points& P = s.points;
  EnergyBudget e;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double v2 = P.velocity[0][p] * P.velocity[0][p] + P.velocity[1][p] * P.velocity[1][p] +
                      P.velocity[2][p] * P.velocity[2][p];
    e.kinetic += 0.5 * P.mass[p] * v2;
    e.internal += P.energy[p] * P.volume0[p];
    e.plastic_work += P.plastic_work[p];
    e.viscous += P.viscous_work[p];
    e.contact -= P.contact_work[p];
  }
  for (const bodies::AbsorbingPoint& a : s.absorbing) e.absorbed += a.absorbed;
  for (const bodies::BodyRange& b : s.bodies) {
    const bodies::Departed& d = b.departed;
    e.viscous += d.viscous_work;
    e.absorbed += d.absorbed;
    e.contact -= d.contact_work;
    e.departed += d.kinetic + d.internal;
  }
  return e;
}

}  // namespace coldspray::metrics
