// A run folder's summary.json, parsed (tests that read what a run reports).
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace coldspray::testing {

inline nlohmann::json read_summary(const std::filesystem::path& run) {
  std::ifstream in(run / "summary.json");
  return nlohmann::json::parse(in);
}

}  // namespace coldspray::testing
