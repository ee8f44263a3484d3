#include "studies/pull_off_fields.hpp"

#include <nlohmann/json.hpp>

namespace coldspray::studies {
namespace {

using Json = nlohmann::ordered_json;

// The peak force over an area, 0 where the area is (no bond, no footprint).
Json strength(double force, double area) { return Json(area > 0.0 ? force / area : 0.0); }

const io::OutputFields<PullOffSummary>& pull_off_fields() {
  static const io::OutputFields<PullOffSummary> fields = {
      {"impact", "-", [](const auto& s) { return Json(s.options.impact.string()); }},
      {"body", "-", [](const auto& s) { return Json(s.body); }},
      {"direction", "-",
       [](const auto& s) {
         return Json::array({s.direction.x(), s.direction.y(), s.direction.z()});
       }},
      {"speed", "m/s", [](const auto& s) { return Json(s.options.speed); }},
      {"peak_force", "N", [](const auto& s) { return Json(s.result.peak_force); }},
      {"peak_displacement", "m", [](const auto& s) { return Json(s.result.peak_displacement); }},
      {"work_of_separation", "J", [](const auto& s) { return Json(s.result.work); }},
      {"final_force", "N", [](const auto& s) { return Json(s.result.final_force); }},
      {"separated", "-", [](const auto& s) { return Json(s.result.separated); }},
      {"bonded_area", "m^2", [](const auto& s) { return Json(s.result.bonded_area); }},
      {"projected_area", "m^2", [](const auto& s) { return Json(s.result.projected_area); }},
      {"strength_bonded", "Pa",
       [](const auto& s) { return strength(s.result.peak_force, s.result.bonded_area); }},
      {"strength_projected", "Pa",
       [](const auto& s) { return strength(s.result.peak_force, s.result.projected_area); }}};
  return fields;
}

}  // namespace

void write_pull_off_summary(const std::filesystem::path& path, const PullOffSummary& s) {
  io::write_fields_file(path, pull_off_fields(), s);
}

io::FieldUnits pull_off_field_units() { return io::field_units(pull_off_fields()); }

}  // namespace coldspray::studies
