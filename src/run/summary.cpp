#include "run/summary.hpp"

#include <nlohmann/json.hpp>
#include <ostream>

#include "io/atomic_file.hpp"

namespace coldspray::run {

void write_summary_json(const Summary& s, const std::filesystem::path& path) {
  nlohmann::ordered_json j;
  j["status"] = s.status;
  j["steps"] = s.steps;
  j["time"] = s.time;
  j["wall_seconds"] = s.wall_seconds;
  j["threads"] = s.threads;
  j["particles"] = s.particles;
  j["particle_steps_per_second"] = s.particle_steps_per_second;
  j["last_dt"] = s.last_dt;
  j["energy"] = {{"kinetic", s.energy.kinetic},
                 {"elastic", s.energy.elastic()},
                 {"plastic_work", s.energy.plastic_work},
                 {"viscous", s.energy.viscous},
                 {"absorbed", s.energy.absorbed},
                 {"contact", s.energy.contact},
                 {"total", s.energy.total()},
                 {"total_initial", s.total_energy_initial},
                 {"relative_error", s.energy_relative_error()}};
  nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
  for (const auto& b : s.bodies)
    bodies[b.name] = {{"mass", b.mass},
                      {"velocity", b.velocity},
                      {"centroid", b.centroid},
                      {"extent_min", b.extent_min},
                      {"extent_max", b.extent_max},
                      {"max_eqps", b.max_eqps},
                      {"mean_eqps", b.mean_eqps},
                      {"max_temperature", b.max_temperature}};
  j["bodies"] = bodies;
  io::write_atomically(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

}  // namespace coldspray::run
