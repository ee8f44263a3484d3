#include "studies/variation.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"
#include "core/units.hpp"

namespace coldspray::studies {

namespace {

[[noreturn]] void bad(const std::string& text, const std::string& why) {
  throw InputError("--vary " + text, "", why);
}

// Splits at commas outside brackets.
std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out(1);
  int depth = 0;
  for (const char ch : list) {
    if (ch == '[') ++depth;
    if (ch == ']') --depth;
    if (ch == ',' && depth == 0)
      out.emplace_back();
    else
      out.back() += ch;
  }
  for (auto& v : out) v = std::string(trim(v));
  return out;
}

std::vector<std::string> range_values(const std::string& text, const std::string& range) {
  const auto first = range.find(':'), second = range.find(':', first + 1);
  units::Quantity q[3];
  try {
    q[0] = units::parse_quantity(trim(range.substr(0, first)));
    q[1] = units::parse_quantity(trim(range.substr(first + 1, second - first - 1)));
    q[2] = units::parse_quantity(trim(range.substr(second + 1)));
  } catch (const UnitError& e) {
    bad(text, e.what());
  }
  if (!(q[0].dimension == q[1].dimension && q[1].dimension == q[2].dimension))
    bad(text, "START, STOP and STEP must have the same unit dimension");
  const double start = q[0].value, stop = q[1].value, step = q[2].value;
  if (!(step > 0.0)) bad(text, "STEP must be > 0");
  if (stop < start) bad(text, "STOP must not be below START");
  // Counted, not accumulated, so that STOP is reached without drift; counted in double and
  // bounded before the conversion, which overflowed for a tiny STEP (0.1:1:1e-20 gave no value).
  const double intervals = std::floor((stop - start) / step * (1.0 + 1e-9));
  if (!(intervals < static_cast<double>(kMaxSweepCases)))
    bad(text, fmt::format("{:.3g} values: at most {} (a larger STEP gives fewer)", intervals + 1.0,
                          kMaxSweepCases));
  const auto count = static_cast<long>(intervals) + 1;
  std::vector<std::string> values;
  for (long i = 0; i < count; ++i) {
    const double v = start + static_cast<double>(i) * step;
    values.push_back(q[0].dimension == units::kDimensionless
                         ? fmt::format("{:.12g}", v)
                         : fmt::format("{:.12g} {}", v, units::si_unit(q[0].dimension)));
  }
  return values;
}

}  // namespace

Variation parse_variation(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    bad(text, "expected KEY=V1,V2,... or KEY=START:STOP:STEP");
  Variation v;
  v.key = std::string(trim(text.substr(0, eq)));
  const std::string rest(trim(text.substr(eq + 1)));
  const bool is_range = rest.find('[') == std::string::npos &&
                        std::count(rest.begin(), rest.end(), ':') == 2 &&
                        rest.find(',') == std::string::npos;
  v.values = is_range ? range_values(text, rest) : split_list(rest);
  for (const auto& value : v.values)
    if (value.empty()) bad(text, "an empty value");
  return v;
}

std::vector<std::vector<case_file::Override>> combinations(const std::vector<Variation>& vary) {
  double count = 1.0;
  for (const Variation& v : vary) count *= static_cast<double>(v.values.size());
  if (count > static_cast<double>(kMaxSweepCases))
    throw InputError(
        "--vary", "",
        fmt::format("{:.3g} combinations of the varied values: at most {}", count, kMaxSweepCases));
  std::vector<std::vector<case_file::Override>> out(1);
  for (const Variation& v : vary) {
    std::vector<std::vector<case_file::Override>> next;
    for (const auto& partial : out)
      for (const auto& value : v.values) {
        auto extended = partial;
        extended.push_back(case_file::parse_override(v.key + "=" + value));
        next.push_back(std::move(extended));
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace coldspray::studies
