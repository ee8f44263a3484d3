#include "run/history.hpp"

#include <fmt/format.h>

#include <string>

namespace coldspray::run {

namespace {

std::string header(const bodies::Bodies& s) {
  std::string h = "time,kinetic,elastic,plastic_work,viscous,absorbed,contact,departed,total";
  for (const auto& b : s.bodies)
    for (const char* q : {"vx", "vy", "vz", "contact_fx", "contact_fy", "contact_fz", "cor",
                          "v_rest", "abp", "pbcp", "mean_eqps", "plastic_energy_density",
                          "max_temperature", "jetted_fraction", "departed_mass", "penetration"})
      h += fmt::format(",{}.{}", b.name, q);
  return h + "\n";
}

}  // namespace

HistoryWriter::HistoryWriter(const bodies::Bodies& s, const std::filesystem::path& path,
                             io::Opening opening)
    : out_(path, header(s), opening) {}

void HistoryWriter::record(double time, const metrics::EnergyBudget& e,
                           const std::vector<metrics::BodyMetrics>& bodies) {
  std::string row = fmt::format(
      "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", time, e.kinetic,
      e.elastic(), e.plastic_work, e.viscous, e.absorbed, e.contact, e.departed, e.total());
  for (const auto& b : bodies) {
    row += fmt::format(",{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", b.velocity[0],
                       b.velocity[1], b.velocity[2], b.contact_force[0], b.contact_force[1],
                       b.contact_force[2]);
    const metrics::ImpactMeasures& m = b.impact;
    row += fmt::format(
        ",{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", m.cor,
        m.v_rest, m.abp, m.pbcp, b.mean_eqps, m.plastic_energy_density, b.max_temperature,
        m.jetted_fraction, b.departed.mass, m.penetration);
  }
  out_.append(row + "\n");
}

}  // namespace coldspray::run
