#include "studies/bulk_fracture_fit.hpp"

#include <nlohmann/json.hpp>

namespace coldspray::studies {
namespace {

using Json = nlohmann::ordered_json;

// A stretch is dimensionless, and so is a work per micromodulus (c s^2 / c).
const io::OutputFields<BulkFractureFit>& bulk_fracture_fit_fields() {
  static const io::OutputFields<BulkFractureFit> fields = {
      {"material", "-", [](const auto& f) { return Json(f.material); }},
      {"spacing", "m", [](const auto& f) { return Json(f.spacing); }},
      {"horizon", "m", [](const auto& f) { return Json(f.horizon); }},
      {"bulk_modulus", "Pa", [](const auto& f) { return Json(f.bulk_modulus); }},
      {"micromodulus", "N/m^6", [](const auto& f) { return Json(f.micromodulus); }},
      {"fracture_energy", "J/m^2", [](const auto& f) { return Json(f.fracture_energy); }},
      {"critical_stretch", "-", [](const auto& f) { return Json(f.critical_stretch); }},
      {"yield_stretch", "-", [](const auto& f) { return Json(f.yield_stretch); }},
      {"softening", "-", [](const auto& f) { return Json(f.softening); }},
      {"break_stretch", "-", [](const auto& f) { return Json(f.break_stretch); }},
      {"work_per_micromodulus_bulk", "-", [](const auto& f) { return Json(f.work_bulk); }},
      {"work_per_micromodulus_fitted", "-", [](const auto& f) { return Json(f.work_fitted); }}};
  return fields;
}

}  // namespace

void write_bulk_fracture_fit(const std::filesystem::path& path, const BulkFractureFit& fit) {
  io::write_fields_file(path, bulk_fracture_fit_fields(), fit);
}

io::FieldUnits bulk_fracture_field_units() { return io::field_units(bulk_fracture_fit_fields()); }

}  // namespace coldspray::studies
