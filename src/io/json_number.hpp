// A number for a JSON file: JSON has no NaN, so an undefined measure (the cor of a body that
// started at rest) is written as null.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace coldspray::io {

inline nlohmann::ordered_json json_number(double x) {
  return std::isnan(x) ? nlohmann::ordered_json() : nlohmann::ordered_json(x);
}

}  // namespace coldspray::io
