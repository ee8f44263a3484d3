#include "studies/deposit_json.hpp"

#include <nlohmann/json.hpp>

#include "io/json_number.hpp"

namespace coldspray::studies {
namespace {

using Json = nlohmann::ordered_json;
using io::json_number;

Json verdict_name(const ParticleRow& r) {
  return r.body->verdict ? Json(metrics::outcome_name(r.body->verdict->outcome)) : Json("none");
}

const io::OutputFields<ParticleRow>& particle_fields() {
  static const io::OutputFields<ParticleRow> fields = {
      {"name", "-", [](const auto& r) { return Json(r.name); }},
      {"diameter", "m", [](const auto& r) { return Json(r.placed->diameter); }},
      {"speed", "m/s", [](const auto& r) { return Json(r.placed->speed); }},
      {"arrival", "s", [](const auto& r) { return Json(r.placed->arrival); }},
      {"centre", "m", [](const auto& r) { return Json(r.placed->centre); }},
      {"verdict", "-", verdict_name},
      {"cor", "-", [](const auto& r) { return json_number(r.body->impact.cor); }},
      {"v_rest", "m/s", [](const auto& r) { return json_number(r.body->impact.v_rest); }},
      {"pbcp", "%", [](const auto& r) { return Json(r.body->impact.pbcp); }},
      {"flattening_ratio", "-",
       [](const auto& r) { return Json(r.body->impact.flattening_ratio); }},
      {"bonded_area", "m^2", [](const auto& r) { return Json(r.body->impact.bonded_area); }},
      {"bonded_area_to_particles", "m^2",
       [](const auto& r) { return Json(r.bonded_to_particles); }},
      {"bonded_area_to_substrate", "m^2",
       [](const auto& r) { return Json(r.bonded_to_substrate); }},
      {"jetted_fraction", "-", [](const auto& r) { return Json(r.body->impact.jetted_fraction); }},
      {"sprayed_mass", "kg", [](const auto& r) { return Json(r.sprayed_mass); }}};
  return fields;
}

// The deposit's top above the substrate's first surface per voxel column, x fastest: the
// thickness map the picture draws.
const io::OutputFields<metrics::DepositShape>& thickness_map_fields() {
  static const io::OutputFields<metrics::DepositShape> fields = {
      {"columns_x", "-", [](const auto& s) { return Json(s.columns[0]); }},
      {"columns_y", "-", [](const auto& s) { return Json(s.columns[1]); }},
      {"values", "m", [](const auto& s) { return Json(s.thickness); }}};
  return fields;
}

Json particles_json(const DepositReport& d) {
  Json particles = Json::array();
  for (const ParticleRow& r : d.rows) particles.push_back(io::write_fields(particle_fields(), r));
  return particles;
}

const io::OutputFields<DepositReport>& deposit_fields() {
  static const io::OutputFields<DepositReport> fields = {
      {"name", "-", [](const auto& d) { return Json(d.name); }},
      {"seed", "-", [](const auto& d) { return Json(d.plan.seed); }},
      {"patch", "m", [](const auto& d) { return Json(d.plan.patch); }},
      {"deposition_efficiency", "-", [](const auto& d) { return Json(d.deposit.efficiency); }},
      {"porosity", "-", [](const auto& d) { return Json(d.deposit.shape.porosity); }},
      {"mean_thickness", "m", [](const auto& d) { return Json(d.deposit.shape.mean_thickness); }},
      {"max_thickness", "m", [](const auto& d) { return Json(d.deposit.shape.max_thickness); }},
      {"coverage", "-", [](const auto& d) { return Json(d.deposit.shape.coverage); }},
      {"voxel", "m", [](const auto& d) { return Json(d.voxel); }},
      {"particles", "-", particles_json},
      {"thickness_map", "-",
       [](const auto& d) { return io::write_fields(thickness_map_fields(), d.deposit.shape); }}};
  return fields;
}

}  // namespace

void write_deposit_json(const std::filesystem::path& path, const DepositReport& report) {
  io::write_fields_file(path, deposit_fields(), report, 1);
}

io::FieldUnits deposit_field_units() {
  io::FieldUnits out;
  io::append_field_units(deposit_fields(), "", out);
  io::append_field_units(particle_fields(), "particles[].", out);
  io::append_field_units(thickness_map_fields(), "thickness_map.", out);
  return out;
}

}  // namespace coldspray::studies
