#include "run/summary.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/json_number.hpp"

namespace coldspray::run {

void write_summary_json(const Summary& s, const std::filesystem::path& path) {
  nlohmann::ordered_json j;
  j["status"] = s.status;
  j["steps"] = s.steps;
  j["time"] = s.time;
  j["wall_seconds"] = s.wall_seconds;
  j["shared_steps"] = s.shared_steps;
  j["threads"] = s.threads;
  j["particles"] = s.particles;
  j["solver"] = {
      {"method", s.discretisation.method},
      {s.discretisation.method == "mpm" ? "cell_size" : "horizon", s.discretisation.length}};
  if (s.discretisation.method == "peridynamics") j["solver"]["bonds"] = s.discretisation.bonds;
  j["particle_steps_per_second"] = s.particle_steps_per_second;
  j["last_dt"] = s.last_dt;
  j["energy"] = {{"kinetic", s.energy.kinetic},
                 {"elastic", s.energy.elastic()},
                 {"plastic_work", s.energy.plastic_work},
                 {"viscous", s.energy.viscous},
                 {"absorbed", s.energy.absorbed},
                 {"contact", s.energy.contact},
                 {"departed", s.energy.departed},
                 {"total", s.energy.total()},
                 {"total_initial", s.total_energy_initial},
                 {"relative_error", s.energy_relative_error()}};
  nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
  const auto number = io::json_number;
  int moving = 0, bonded = 0, undecided = 0;
  std::vector<metrics::ImpactMeasures> measures;
  for (const auto& b : s.bodies) {
    const metrics::ImpactMeasures& m = b.impact;
    measures.push_back(m);
    // Bonded area by partner, for the bodies it holds to (thesis Table 5.5's pairs).
    nlohmann::ordered_json with = nlohmann::ordered_json::object();
    for (std::size_t o = 0; o < m.bonded_area_with.size() && o < s.bodies.size(); ++o)
      if (m.bonded_area_with[o] > 0.0) with[s.bodies[o].name] = m.bonded_area_with[o];
    bodies[b.name] = {{"mass", b.mass},
                      {"velocity", b.velocity},
                      {"centroid", b.centroid},
                      {"extent_min", b.extent_min},
                      {"extent_max", b.extent_max},
                      {"max_eqps", b.max_eqps},
                      {"mean_eqps", b.mean_eqps},
                      {"max_temperature", b.max_temperature},
                      {"cor", number(m.cor)},
                      {"v_rest", number(m.v_rest)},
                      {"abp", m.abp},
                      {"pbcp", m.pbcp},
                      {"plastic_energy_density", m.plastic_energy_density},
                      {"jetted_fraction", m.jetted_fraction},
                      {"crater_depth", m.crater_depth},
                      {"flattening_ratio", m.flattening_ratio},
                      {"penetration", number(m.penetration)},
                      {"penetration_peak_time", number(m.penetration_peak_time)},
                      {"contact_area", m.contact_area},
                      {"bonded_area", m.bonded_area},
                      {"bonded_area_with", with},
                      {"departed",
                       {{"points", b.departed.points},
                        {"mass", b.departed.mass},
                        {"momentum", b.departed.momentum},
                        {"kinetic_energy", b.departed.kinetic},
                        {"internal_energy", b.departed.internal},
                        {"plastic_work", b.departed.plastic_work}}}};
    if (!b.verdict) continue;
    const metrics::Verdict& v = *b.verdict;
    ++moving;
    bonded += v.outcome == metrics::Outcome::Bonded;
    undecided += v.outcome == metrics::Outcome::Undecided;
    bodies[b.name]["verdict"] = {{"outcome", metrics::outcome_name(v.outcome)},
                                 {"separation_speed", number(v.separation_speed)},
                                 {"margin", number(v.margin)},
                                 {"settling", number(v.settling)},
                                 {"window", v.window}};
  }
  j["bodies"] = bodies;
  // The verdict over the bodies that moved in z at t = 0 (the particles): bonded when every one
  // is, rebounded when one is, else undecided.
  const char* outcome = moving == 0                    ? nullptr
                        : bonded == moving             ? "bonded"
                        : bonded + undecided == moving ? "undecided"
                                                       : "rebounded";
  j["system"] = {{"outcome", outcome ? nlohmann::ordered_json(outcome) : nlohmann::ordered_json()},
                 {"bonded", moving > 0 && bonded == moving},
                 {"moving_bodies", moving},
                 {"bonded_bodies", bonded},
                 {"undecided_bodies", undecided},
                 {"pbcp", metrics::system_pbcp(measures)},
                 {"extensions", s.extensions}};
  io::write_atomically(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

}  // namespace coldspray::run
