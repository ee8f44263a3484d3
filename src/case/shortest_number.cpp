#include "case/shortest_number.hpp"

#include <fmt/format.h>

#include <charconv>
#include <limits>

namespace coldspray::case_file {

namespace {

// The fewest significant digits in %g style: "2.6e+10", but also "2.7e+03" for 2700.
std::string shortest_general(double value) {
  constexpr int kMaxDigits = std::numeric_limits<double>::max_digits10;
  for (int digits = 1; digits < kMaxDigits; ++digits) {
    std::string text = fmt::format("{:.{}g}", value, digits);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    if (back == value) return text;
  }
  return fmt::format("{:.{}g}", value, kMaxDigits);
}

}  // namespace

std::string shortest_text(double value) {
  // fmt's default is the shortest round trip too, but written out in full ("2700",
  // "26000000000"); take whichever of the two forms is shorter.
  std::string plain = fmt::format("{}", value);
  std::string general = shortest_general(value);
  return general.size() <= plain.size() ? general : plain;
}

}  // namespace coldspray::case_file
