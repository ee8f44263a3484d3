// What the schema says about a field besides its type: whether it must be given, and the range
// its value must lie in.
#pragma once

#include <limits>
#include <string>

namespace coldspray::case_file {

enum class Presence { Required, Optional };
inline constexpr Presence kRequired = Presence::Required;
inline constexpr Presence kOptional = Presence::Optional;

// An interval of allowed values; each end open or closed, infinite ends allowed.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;

  bool contains(double value) const;
  // "> 0", ">= 0", "in (0, 1]", ...: completes "must be ...".
  std::string describe() const;
};

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr Range kAnyValue{};
inline constexpr Range kPositive{0.0, kInfinity, true, false};
inline constexpr Range kNonNegative{0.0, kInfinity, false, false};
inline constexpr Range kFraction{0.0, 1.0, true, false};       // (0, 1]
inline constexpr Range kUnitInterval{0.0, 1.0, false, false};  // [0, 1]
inline constexpr Range kPoissonRatio{-1.0, 0.5, true, true};   // (-1, 0.5)

}  // namespace coldspray::case_file
