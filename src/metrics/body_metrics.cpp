#include "metrics/body_metrics.hpp"

#include <algorithm>
#include <limits>

namespace coldspray::metrics {

std::vector<BodyMetrics> body_metrics(const bodies::Bodies& s, SplatExtent extent) {
  const bodies::Points& P = s.points;
  const std::size_t bodies = s.bodies.size();
  std::vector<BodyMetrics> out;
  for (std::size_t b = 0; b < bodies; ++b) {
    const bodies::BodyRange& r = s.bodies[b];
    BodyMetrics m;
    m.name = r.name;
    m.extent_min.fill(std::numeric_limits<double>::max());
    m.extent_max.fill(std::numeric_limits<double>::lowest());
    double eqps_sum = 0.0;
    for (std::size_t p = r.begin; p < r.end; ++p) {
      const double mp = P.mass[p];
      m.mass += mp;
      for (int d = 0; d < 3; ++d) {
        m.velocity[d] += mp * P.velocity[d][p];
        m.centroid[d] += mp * P.position[d][p];
        m.extent_min[d] = std::min(m.extent_min[d], P.position[d][p]);
        m.extent_max[d] = std::max(m.extent_max[d], P.position[d][p]);
      }
      m.max_eqps = std::max(m.max_eqps, P.eqps[p]);
      eqps_sum += mp * P.eqps[p];
      m.max_temperature = std::max(m.max_temperature, P.temperature[p]);
    }
    for (int d = 0; d < 3; ++d) {
      m.velocity[d] /= m.mass;
      m.centroid[d] /= m.mass;
    }
    m.mean_eqps = eqps_sum / m.mass;
    if (s.dt > 0.0)
      for (std::size_t o = 0; o < bodies; ++o)
        for (int d = 0; d < 3; ++d)
          m.contact_force[d] += s.contact_impulse[b * bodies + o][d] / s.dt;
    m.impact = impact_measures(s, b, extent);
    m.departed = r.departed;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace coldspray::metrics
