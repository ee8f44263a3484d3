// `coldspray bulk-fracture`'s fit.json (docs/outputs.md, "Bulk-fracture fit.json"), written from
// declared fields (io/output_schema.hpp): the bulk's constants and eq 24's fit to its curve.
#pragma once

#include <filesystem>
#include <string>

#include "io/output_schema.hpp"

namespace coldspray::studies {

// The bulk-fracture test's constants and the fitted interface law (pd/bulk_fracture.hpp), the
// law as its numbers: studies/ does not include pd/ (tests/layering).
struct BulkFractureFit {
  std::string material;
  double spacing = 0.0;           // m
  double horizon = 0.0;           // m
  double bulk_modulus = 0.0;      // Pa
  double micromodulus = 0.0;      // c = 18 K / (pi delta^4), N/m^6
  double fracture_energy = 0.0;   // G_c, J/m^2
  double critical_stretch = 0.0;  // s_c, eq 23
  double yield_stretch = 0.0;     // s_y of eq 24 at s_c
  double softening = 0.0;         // m
  double break_stretch = 0.0;     // s_y + ln(1 / kBreakFraction) / m
  double work_bulk = 0.0;         // the bulk curve's work to its break, per micromodulus
  double work_fitted = 0.0;       // the fitted law's, per micromodulus
};

// Writes fit.json at `path`.
void write_bulk_fracture_fit(const std::filesystem::path& path, const BulkFractureFit& fit);

// Its fields with their units, in written order: docs/outputs.md's table lists the same
// (tests/run/output_fields_test.cpp).
io::FieldUnits bulk_fracture_field_units();

}  // namespace coldspray::studies
