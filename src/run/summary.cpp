#include "run/summary.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "io/json_number.hpp"
#include "io/output_schema.hpp"

namespace coldspray::run {
namespace {

using Json = nlohmann::ordered_json;
using io::json_number;

// One body's entry: the body and the run it is in (for its partners' names).
struct BodyEntry {
  const Summary& run;
  const metrics::BodyMetrics& body;
};

// The verdict over the bodies that moved in z at t = 0 (the particles).
struct SystemTally {
  const Summary& run;
  int moving = 0, bonded = 0, undecided = 0;
  std::vector<metrics::ImpactMeasures> measures;
};

const io::OutputFields<bodies::Discretisation>& solver_fields() {
  static const io::OutputFields<bodies::Discretisation> fields = {
      {"method", "-", [](const auto& d) { return Json(d.method); }},
      // The MPM's cell size or the smallest PD horizon, named by the discretisation.
      {"cell_size or horizon", "m", [](const auto& d) { return Json(d.length); },
       [](const auto& d) { return d.length_name; }},
      {"bonds", "-", [](const auto& d) { return d.bonds ? Json(*d.bonds) : io::absent_field(); }}};
  return fields;
}

const io::OutputFields<Summary>& energy_fields() {
  static const io::OutputFields<Summary> fields = {
      {"kinetic", "J", [](const auto& s) { return Json(s.energy.kinetic); }},
      {"elastic", "J", [](const auto& s) { return Json(s.energy.elastic()); }},
      {"plastic_work", "J", [](const auto& s) { return Json(s.energy.plastic_work); }},
      {"viscous", "J", [](const auto& s) { return Json(s.energy.viscous); }},
      {"absorbed", "J", [](const auto& s) { return Json(s.energy.absorbed); }},
      {"contact", "J", [](const auto& s) { return Json(s.energy.contact); }},
      {"departed", "J", [](const auto& s) { return Json(s.energy.departed); }},
      {"total", "J", [](const auto& s) { return Json(s.energy.total()); }},
      {"total_initial", "J", [](const auto& s) { return Json(s.total_energy_initial); }},
      {"relative_error", "-", [](const auto& s) { return Json(s.energy_relative_error()); }}};
  return fields;
}

const io::OutputFields<bodies::Departed>& departed_fields() {
  static const io::OutputFields<bodies::Departed> fields = {
      {"points", "-", [](const auto& d) { return Json(d.points); }},
      {"mass", "kg", [](const auto& d) { return Json(d.mass); }},
      {"momentum", "kg m/s", [](const auto& d) { return Json(d.momentum); }},
      {"kinetic_energy", "J", [](const auto& d) { return Json(d.kinetic); }},
      {"internal_energy", "J", [](const auto& d) { return Json(d.internal); }},
      {"plastic_work", "J", [](const auto& d) { return Json(d.plastic_work); }}};
  return fields;
}

const io::OutputFields<metrics::Verdict>& verdict_fields() {
  static const io::OutputFields<metrics::Verdict> fields = {
      {"outcome", "-", [](const auto& v) { return Json(metrics::outcome_name(v.outcome)); }},
      {"separation_speed", "m/s", [](const auto& v) { return json_number(v.separation_speed); }},
      {"margin", "m/s", [](const auto& v) { return json_number(v.margin); }},
      {"settling", "m/s", [](const auto& v) { return json_number(v.settling); }},
      {"window", "s", [](const auto& v) { return Json(v.window); }}};
  return fields;
}

// Bonded area by partner, for the bodies it holds to (thesis Table 5.5's pairs).
Json bonded_area_with(const BodyEntry& e) {
  const std::vector<double>& area = e.body.impact.bonded_area_with;
  Json with = Json::object();
  for (std::size_t o = 0; o < area.size() && o < e.run.bodies.size(); ++o)
    if (area[o] > 0.0) with[e.run.bodies[o].name] = area[o];
  return with;
}

const io::OutputFields<BodyEntry>& body_fields() {
  static const io::OutputFields<BodyEntry> fields = {
      {"mass", "kg", [](const auto& e) { return Json(e.body.mass); }},
      {"velocity", "m/s", [](const auto& e) { return Json(e.body.velocity); }},
      {"centroid", "m", [](const auto& e) { return Json(e.body.centroid); }},
      {"extent_min", "m", [](const auto& e) { return Json(e.body.extent_min); }},
      {"extent_max", "m", [](const auto& e) { return Json(e.body.extent_max); }},
      {"max_eqps", "-", [](const auto& e) { return Json(e.body.max_eqps); }},
      {"mean_eqps", "-", [](const auto& e) { return Json(e.body.mean_eqps); }},
      {"max_temperature", "K", [](const auto& e) { return Json(e.body.max_temperature); }},
      {"cor", "-", [](const auto& e) { return json_number(e.body.impact.cor); }},
      {"v_rest", "m/s", [](const auto& e) { return json_number(e.body.impact.v_rest); }},
      {"abp", "-", [](const auto& e) { return Json(e.body.impact.abp); }},
      {"pbcp", "%", [](const auto& e) { return Json(e.body.impact.pbcp); }},
      {"plastic_energy_density", "J/m^3",
       [](const auto& e) { return Json(e.body.impact.plastic_energy_density); }},
      {"jetted_fraction", "-", [](const auto& e) { return Json(e.body.impact.jetted_fraction); }},
      {"crater_depth", "m", [](const auto& e) { return Json(e.body.impact.crater_depth); }},
      {"flattening_ratio", "-", [](const auto& e) { return Json(e.body.impact.flattening_ratio); }},
      {"penetration", "m", [](const auto& e) { return json_number(e.body.impact.penetration); }},
      {"penetration_peak_time", "s",
       [](const auto& e) { return json_number(e.body.impact.penetration_peak_time); }},
      {"contact_area", "m^2", [](const auto& e) { return Json(e.body.impact.contact_area); }},
      {"bonded_area", "m^2", [](const auto& e) { return Json(e.body.impact.bonded_area); }},
      {"bonded_area_with", "m^2", bonded_area_with},
      {"departed", "-",
       [](const auto& e) { return io::write_fields(departed_fields(), e.body.departed); }},
      {"verdict", "-", [](const auto& e) {
         return e.body.verdict ? io::write_fields(verdict_fields(), *e.body.verdict)
                               : io::absent_field();
       }}};
  return fields;
}

// Bonded when every moving body is, rebounded when one is, else undecided.
Json system_outcome(const SystemTally& t) {
  if (t.moving == 0) return Json();
  return t.bonded == t.moving                 ? "bonded"
         : t.bonded + t.undecided == t.moving ? "undecided"
                                              : "rebounded";
}

const io::OutputFields<SystemTally>& system_fields() {
  static const io::OutputFields<SystemTally> fields = {
      {"outcome", "-", system_outcome},
      {"bonded", "-", [](const auto& t) { return Json(t.moving > 0 && t.bonded == t.moving); }},
      {"moving_bodies", "-", [](const auto& t) { return Json(t.moving); }},
      {"bonded_bodies", "-", [](const auto& t) { return Json(t.bonded); }},
      {"undecided_bodies", "-", [](const auto& t) { return Json(t.undecided); }},
      {"pbcp", "%", [](const auto& t) { return Json(metrics::system_pbcp(t.measures)); }},
      {"extensions", "-", [](const auto& t) { return Json(t.run.extensions); }}};
  return fields;
}

Json bodies_json(const Summary& s) {
  Json bodies = Json::object();
  for (const auto& b : s.bodies) bodies[b.name] = io::write_fields(body_fields(), {s, b});
  return bodies;
}

Json system_json(const Summary& s) {
  SystemTally t{s, 0, 0, 0, {}};
  for (const auto& b : s.bodies) {
    t.measures.push_back(b.impact);
    if (!b.verdict) continue;
    ++t.moving;
    t.bonded += b.verdict->outcome == metrics::Outcome::Bonded;
    t.undecided += b.verdict->outcome == metrics::Outcome::Undecided;
  }
  return io::write_fields(system_fields(), t);
}

const io::OutputFields<Summary>& summary_fields() {
  static const io::OutputFields<Summary> fields = {
      {"status", "-", [](const auto& s) { return Json(s.status); }},
      {"steps", "-", [](const auto& s) { return Json(s.steps); }},
      {"time", "s", [](const auto& s) { return Json(s.time); }},
      {"wall_seconds", "s", [](const auto& s) { return Json(s.wall_seconds); }},
      {"shared_steps", "-", [](const auto& s) { return Json(s.shared_steps); }},
      {"threads", "-", [](const auto& s) { return Json(s.threads); }},
      {"particles", "-", [](const auto& s) { return Json(s.particles); }},
      {"solver", "-",
       [](const auto& s) { return io::write_fields(solver_fields(), s.discretisation); }},
      {"particle_steps_per_second", "1/s",
       [](const auto& s) { return Json(s.particle_steps_per_second); }},
      {"last_dt", "s", [](const auto& s) { return Json(s.last_dt); }},
      {"energy", "-", [](const auto& s) { return io::write_fields(energy_fields(), s); }},
      {"bodies", "-", bodies_json},
      {"system", "-", system_json}};
  return fields;
}

}  // namespace

io::FieldUnits summary_field_units() {
  io::FieldUnits out;
  io::append_field_units(summary_fields(), "", out);
  io::append_field_units(solver_fields(), "solver.", out);
  io::append_field_units(energy_fields(), "energy.", out);
  io::append_field_units(body_fields(), "bodies.<name>.", out);
  io::append_field_units(departed_fields(), "bodies.<name>.departed.", out);
  io::append_field_units(verdict_fields(), "bodies.<name>.verdict.", out);
  io::append_field_units(system_fields(), "system.", out);
  return out;
}

void write_summary_json(const Summary& s, const std::filesystem::path& path) {
  io::write_fields_file(path, summary_fields(), s);
}

}  // namespace coldspray::run
