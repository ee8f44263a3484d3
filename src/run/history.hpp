// history.csv: the energy budget and each body's velocity and contact force over time.
#pragma once

#include <filesystem>

#include "bodies/bodies.hpp"
#include "io/appended_file.hpp"
#include "metrics/body_metrics.hpp"
#include "metrics/energy.hpp"

namespace coldspray::run {

class HistoryWriter {
 public:
  HistoryWriter(const bodies::Bodies& s, const std::filesystem::path& path, io::Opening opening);
  void record(double time, const metrics::EnergyBudget& e,
              const std::vector<metrics::BodyMetrics>& bodies);
  const io::AppendedFile& file() const { return out_; }

 private:
  io::AppendedFile out_;
};

}  // namespace coldspray::run
