#include "verification_support.hpp"

#include <stdexcept>

#include "case/load.hpp"
#include "run/run.hpp"
#include "temp_dir.hpp"

namespace coldspray::verification {

CaseRun run_verification_case(const std::string& name,
                              const std::vector<std::pair<std::string, std::string>>& sets) {
  std::vector<case_file::Override> overrides;
  for (const auto& [k, v] : sets) overrides.push_back({k, v});
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/" + name + ".yaml", overrides);
  const std::string dir = testing::make_temp_dir("verify-" + name);
  run::RunOptions options;
  options.out_dir = dir;
  options.progress = false;
  CaseRun r;
  r.summary = run::run_case(c, options);
  r.out_dir = dir;
  return r;
}

double crossing_time(const std::vector<double>& time, const std::vector<double>& values,
                     double level) {
  const bool rising = values.front() < level;
  for (std::size_t i = 1; i < values.size(); ++i) {
    const bool crossed = rising ? values[i] >= level : values[i] <= level;
    if (crossed) {
      const double f = (level - values[i - 1]) / (values[i] - values[i - 1]);
      return time[i - 1] + f * (time[i] - time[i - 1]);
    }
  }
  return -1.0;
}

double mean_over(const std::vector<double>& time, const std::vector<double>& values, double t0,
                 double t1) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < time.size(); ++i)
    if (time[i] >= t0 && time[i] <= t1) {
      sum += values[i];
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

}  // namespace coldspray::verification
