// A calibration's calibration.json (docs/outputs.md, "calibration.json"), written from declared
// fields (io/output_schema.hpp): the plan's parameters and fit options, and per grid each size's
// counts, classification and fit and the sizes' crossing; and the activation calibration's
// (docs/outputs.md, "Activation calibration.json"): per grid each size's penetration law and the
// calibrated critical penetration.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/output_schema.hpp"
#include "studies/activation_calibration.hpp"
#include "studies/calibration.hpp"

namespace coldspray::studies {

// Writes out_dir / calibration.json.
void write_calibration_json(const CalibrationPlan& plan, const std::vector<GridResult>& results,
                            const std::filesystem::path& out_dir, const std::string& name);

// Its fields with their units, in written order: docs/outputs.md's table lists the same
// (tests/run/output_fields_test.cpp).
io::FieldUnits calibration_field_units();

// Writes the activation calibration's out_dir / calibration.json.
void write_activation_json(const ActivationPlan& plan,
                           const std::vector<ActivationGridResult>& results,
                           const std::filesystem::path& out_dir, const std::string& name);

// Its fields with their units, in written order, as calibration_field_units.
io::FieldUnits activation_field_units();

}  // namespace coldspray::studies
