// The pull-off's summary.json (docs/outputs.md, "Pull-off summary.json"), written from declared
// fields (io/output_schema.hpp): what was pulled, how, and what the pull measured.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "io/output_schema.hpp"
#include "studies/pull_off.hpp"

namespace coldspray::studies {

// One pull-off's outcome: its options, its measures, the gripped body and the pull's direction.
struct PullOffSummary {
  const PullOffOptions& options;
  const PullOffResult& result;
  std::string body;
  Eigen::Vector3d direction;
};

// Writes the pull-off's summary.json at `path`.
void write_pull_off_summary(const std::filesystem::path& path, const PullOffSummary& s);

// Its fields with their units, in written order: docs/outputs.md's table lists the same
// (tests/run/output_fields_test.cpp).
io::FieldUnits pull_off_field_units();

}  // namespace coldspray::studies
