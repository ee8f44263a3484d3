#include "run/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "bodies/material_state.hpp"
#include "materials/symmetric_tensor.hpp"

namespace coldspray::run {

namespace {

constexpr std::array<const char*, 14> kFields = {
    "pressure", "von_mises", "density",  "temperature", "eqps",       "sigma_xx",   "sigma_yy",
    "sigma_zz", "sigma_xy",  "sigma_yz", "sigma_xz",    "velocity_x", "velocity_y", "velocity_z"};

std::size_t nearest_point(const bodies::Bodies& s, const case_file::Vec3& x) {
  const bodies::Points& P = s.points;
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::max();
  for (std::size_t p = 0; p < P.size(); ++p) {
    double d2 = 0.0;
    for (int d = 0; d < 3; ++d) d2 += (P.position[d][p] - x[d]) * (P.position[d][p] - x[d]);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = p;
    }
  }
  return best;
}

// The point's index now, if it is still on the grid: ids ascend within a body.
std::optional<std::size_t> find_point(const bodies::Bodies& s, std::uint16_t body,
                                      std::uint32_t id) {
  const bodies::BodyRange& r = s.bodies[body];
  const auto first = s.points.id.begin();
  const auto at = std::lower_bound(first + static_cast<std::ptrdiff_t>(r.begin),
                                   first + static_cast<std::ptrdiff_t>(r.end), id);
  if (at == first + static_cast<std::ptrdiff_t>(r.end) || *at != id) return std::nullopt;
  return static_cast<std::size_t>(at - first);
}

}  // namespace

int probe_field_index(const std::string& name) {
  for (std::size_t i = 0; i < kFields.size(); ++i)
    if (name == kFields[i]) return static_cast<int>(i);
  return -1;
}

double probe_value(const bodies::Bodies& s, std::size_t p, int field) {
  const bodies::Points& P = s.points;
  switch (field) {
    case 0:
      return materials::mean_pressure(bodies::stress_at(P, p));
    case 1:
      return materials::von_mises_stress(bodies::stress_at(P, p));
    case 2:
      return s.bodies[P.body[p]].material.density / P.J[p];
    case 3:
      return P.temperature[p];
    case 4:
      return P.eqps[p];
    default:
      if (field >= 5 && field <= 10) return P.stress[field - 5][p];
      return P.velocity[field - 11][p];
  }
}

ProbeWriter::ProbeWriter(const std::vector<case_file::Probe>& probes, const bodies::Bodies& s,
                         const std::filesystem::path& path, io::Opening opening) {
  if (probes.empty()) return;
  std::string header = "time";
  for (const auto& probe : probes) {
    const std::size_t p = nearest_point(s, probe.position);
    for (const auto& f : probe.fields) {
      columns_.push_back({s.points.body[p], s.points.id[p], probe_field_index(f)});
      header += fmt::format(",{}.{}", probe.name, f);
    }
  }
  out_.emplace(path, header + "\n", opening);
}

void ProbeWriter::record(const bodies::Bodies& s) {
  if (columns_.empty()) return;
  std::string row = fmt::format("{:.10g}", s.time);
  for (const Column& c : columns_) {
    const std::optional<std::size_t> p = find_point(s, c.body, c.id);
    row += fmt::format(",{:.10g}",
                       p ? probe_value(s, *p, c.field) : std::numeric_limits<double>::quiet_NaN());
  }
  out_->append(row + "\n");
}

}  // namespace coldspray::run
