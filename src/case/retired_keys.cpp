#include "case/retired_keys.hpp"

#include <array>
#include <utility>

namespace coldspray::case_file {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kRetired{{
    {"metrics.bonded_rest_speed",
     "was removed: the bonded verdict no longer reads v_rest at one instant but the mean "
     "separation speed over the run's last window; use metrics.bonded_separation_speed "
     "(default 2 m/s) and metrics.verdict_window (default 20 ns), docs/bonding.md#the-verdict"},
    {"metrics.bonded_pbcp",
     "was removed: PBCP does not separate bonded from rebounding particles in this model, and "
     "the verdict needs bonded area that holds and a mean separation speed of at most "
     "metrics.bonded_separation_speed instead, docs/bonding.md#the-verdict"},
}};

}  // namespace

std::optional<std::string_view> retired_key(std::string_view path) {
  for (const auto& [key, why] : kRetired)
    if (key == path) return why;
  return std::nullopt;
}

}  // namespace coldspray::case_file
