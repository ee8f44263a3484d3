#include "core/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "core/error.hpp"
#include "core/text.hpp"

namespace coldspray::units {

namespace {

// Every accepted unit is a power of ten times a coherent SI unit, so a conversion is a shift of
// the decimal exponent: "14 um" becomes "14e-6", which from_chars rounds correctly.
struct Unit {
  std::string_view symbol;
  Dimension dimension;
  int exponent10 = 0;  // the unit in SI is 10^exponent10
  bool takes_prefix = true;
};

constexpr std::array kUnits{
    Unit{"m", kLength},    Unit{"s", kTime},
    Unit{"g", kMass, -3},  Unit{"K", kTemperature, 0, false},
    Unit{"Pa", kPressure}, Unit{"J", kEnergy},
    Unit{"N", kForce},     Unit{"W", kEnergy / kTime},
};

struct Prefix {
  std::string_view symbol;
  int exponent10 = 0;
};

// u, the micro sign and the Greek mu all stand for micro.
constexpr std::array kPrefixes{
    Prefix{"n", -9}, Prefix{"u", -6}, Prefix{"\u00b5", -6}, Prefix{"\u03bc", -6}, Prefix{"m", -3},
    Prefix{"c", -2}, Prefix{"k", 3},  Prefix{"M", 6},       Prefix{"G", 9},
};

constexpr std::array<std::string_view, 8> kTemperatureScales{
    "degC", "degF", "C", "F", "\u00b0C", "\u00b0F", "celsius", "fahrenheit"};

// Powers of units, and of the base dimensions they add up to, stay within +-kMaxPower: no
// physical quantity needs more, and the sums of powers and of decimal exponents then cannot
// overflow an int.
constexpr int kMaxPower = 12;

constexpr std::string_view kKnownUnits =
    "known units: m, s, g, kg, K, Pa, J, N, W; prefixes n, u, m, c, k, M, G (not on K)";

// A unit symbol with its prefix applied.
struct Factor {
  Dimension dimension;
  int exponent10 = 0;
};

std::optional<Factor> find_unit(std::string_view symbol) {
  for (const Unit& u : kUnits) {
    if (symbol == u.symbol) return Factor{u.dimension, u.exponent10};
  }
  for (const Prefix& p : kPrefixes) {
    if (!symbol.starts_with(p.symbol)) continue;
    for (const Unit& u : kUnits) {
      if (u.takes_prefix && symbol.substr(p.symbol.size()) == u.symbol) {
        return Factor{u.dimension, u.exponent10 + p.exponent10};
      }
    }
  }
  return std::nullopt;
}

bool is_temperature_scale(std::string_view symbol) {
  for (std::string_view scale : kTemperatureScales) {
    if (symbol == scale) return true;
  }
  return false;
}

bool is_symbol_char(char c) {
  // Letters, and the bytes of the UTF-8 micro sign, Greek mu and degree sign.
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || (static_cast<unsigned char>(c) & 0x80);
}

// Reads a unit expression: UNIT[^INT] (('*' | '/') UNIT[^INT])*, with "1" allowed as the first
// factor ("1/s"). Each '/' divides by the one factor that follows, left to right.
class UnitExpression {
 public:
  UnitExpression(std::string_view expression, std::string_view whole)
      : text_(expression), whole_(whole) {}

  Factor parse() {
    Factor total;
    skip_spaces();
    if (peek() == '1') {
      ++pos_;
      skip_spaces();
      if (peek() != '/') fail("'1' may only start a unit written as 1/UNIT");
    } else {
      total = factor();
    }
    while (true) {
      skip_spaces();
      if (pos_ == text_.size()) return total;
      const char op = text_[pos_];
      if (op != '*' && op != '/') fail(unexpected());
      ++pos_;
      skip_spaces();
      total = combine(total, factor(), op);
    }
  }

 private:
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }

  void skip_spaces() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  Factor factor() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_symbol_char(text_[pos_])) ++pos_;
    const std::string_view symbol = text_.substr(start, pos_ - start);
    if (symbol.empty()) fail(unexpected());
    if (is_temperature_scale(symbol)) {
      fail("temperatures are given in K only ('" + std::string(symbol) +
           "' is not accepted; 20 degC is 293.15 K)");
    }
    const std::optional<Factor> unit = find_unit(symbol);
    if (!unit) {
      fail("unknown unit '" + std::string(symbol) + "' (" + std::string(kKnownUnits) + ")");
    }
    const int power = exponent();
    return {unit->dimension.pow(power), unit->exponent10 * power};
  }

  int exponent() {
    if (peek() != '^') return 1;
    ++pos_;
    int power = 0;
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    const auto [end, ec] = std::from_chars(first, last, power);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && std::abs(power) > kMaxPower))
      fail(fmt::format("a power must lie between -{0} and {0}", kMaxPower));
    if (ec != std::errc() || power == 0) fail("'^' must be followed by a non-zero integer power");
    pos_ += static_cast<std::size_t>(end - first);
    return power;
  }

  // The product so far times f (or divided by f), refused once a base dimension's power leaves
  // +-kMaxPower: bounded powers keep every sum in an int, however many factors there are.
  Factor combine(const Factor& total, const Factor& f, char op) const {
    const Factor out = op == '*'
                           ? Factor{total.dimension * f.dimension, total.exponent10 + f.exponent10}
                           : Factor{total.dimension / f.dimension, total.exponent10 - f.exponent10};
    const Dimension& d = out.dimension;
    for (const int p : {d.mass, d.length, d.time, d.temperature})
      if (std::abs(p) > kMaxPower)
        fail(fmt::format("the unit's powers must lie between -{0} and {0}", kMaxPower));
    // Prefixes that cancel in dimension (um/m) still scale: beyond 1e+-1000 no double is left.
    if (std::abs(out.exponent10) > 1000) fail("the unit's scale is out of range");
    return out;
  }

  std::string unexpected() const {
    if (pos_ == text_.size()) return "unit expression ends early";
    return "unexpected '" + std::string(1, text_[pos_]) +
           "' in the unit (write units as e.g. kg/m^3 or J/kg/K, with '*' between factors)";
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw UnitError("'" + std::string(whole_) + "': " + message);
  }

  std::string_view text_;
  std::string_view whole_;
  std::size_t pos_ = 0;
};

// A number as written: [+|-] DIGITS [. DIGITS] [(e|E) [+|-] DIGITS], at least one digit before
// the exponent. Every form std::to_chars, printf's %g/%e and people write ("1e+12", "1.5E-03",
// "+3", ".5", "5.") is one; hexadecimal, inf and nan are not. Reading the syntax here, rather
// than taking whatever prefix std::from_chars accepts, is what makes "1e+", "1e3.5" or "+-3" an
// error instead of another number.
struct WrittenNumber {
  std::string mantissa;    // the sign ('-' only) and the digits with their point
  long long exponent = 0;  // the written exponent, saturated at +-kMaxWrittenExponent
  std::size_t length = 0;  // characters of the text the number spans
};

// Beyond this the value is 0 or out of range for any mantissa shorter than a gigabyte, and the
// sum with a unit's shift (at most 1000, UnitExpression::combine) stays far inside an int.
constexpr long long kMaxWrittenExponent = 1'000'000'000;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::size_t digits_from(std::string_view text, std::size_t pos) {
  std::size_t end = pos;
  while (end < text.size() && is_digit(text[end])) ++end;
  return end - pos;
}

bool starts_with_word(std::string_view text, std::string_view word) {
  if (text.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != word[i]) return false;
  return true;
}

[[noreturn]] void not_a_number(std::string_view whole, std::string_view why) {
  throw UnitError("'" + std::string(whole) + "' is not a number" + std::string(why));
}

// The exponent after 'e' or 'E' at text[pos]: [+|-] DIGITS; sets n.exponent and n.length.
void read_exponent(std::string_view text, std::size_t pos, WrittenNumber& n) {
  const bool negative = pos < text.size() && text[pos] == '-';
  if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) ++pos;
  const std::size_t digits = digits_from(text, pos);
  if (digits == 0) not_a_number(text, ": 'e' must be followed by a whole exponent, e.g. 1e-3");
  long long magnitude = 0;
  for (std::size_t i = pos; i < pos + digits; ++i)
    magnitude = std::min(kMaxWrittenExponent, magnitude * 10 + (text[i] - '0'));
  n.exponent = negative ? -magnitude : magnitude;
  n.length = pos + digits;
}

// Reads the number that starts `text` (trimmed); UnitError unless it is one as defined above.
WrittenNumber read_number(std::string_view text) {
  std::size_t pos = 0;
  if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) ++pos;
  const std::string_view rest = text.substr(pos);
  if (starts_with_word(rest, "inf") || starts_with_word(rest, "nan"))
    throw UnitError("'" + std::string(text) + "': value must be a finite number");
  const std::size_t whole_digits = digits_from(text, pos);
  std::size_t end = pos + whole_digits;
  std::size_t fraction_digits = 0;
  if (end < text.size() && text[end] == '.') {
    fraction_digits = digits_from(text, end + 1);
    end += 1 + fraction_digits;
  }
  if (whole_digits + fraction_digits == 0) not_a_number(text, "");
  const bool hex_prefix = end == pos + 1 && text[pos] == '0' && end < text.size() &&
                          (text[end] == 'x' || text[end] == 'X');
  if (hex_prefix) not_a_number(text, " (hexadecimal is not accepted)");
  WrittenNumber n;
  const std::size_t plus = text[0] == '+' ? 1 : 0;  // from_chars takes no '+'
  n.mantissa = std::string(text.substr(plus, end - plus));
  n.length = end;
  if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) read_exponent(text, end + 1, n);
  // No unit starts with these: "1.2.3", "1e3.5", "1e3e2" and "1+2" are malformed numbers.
  if (n.length < text.size() &&
      std::string_view(".+-eE").find(text[n.length]) != std::string_view::npos)
    not_a_number(text, "");
  return n;
}

// The number times 10^shift, rounded once: the shift is added to the decimal exponent and
// from_chars rounds the exact decimal to the nearest double. A value that overflows, or that
// is not zero and rounds to zero, is out of range (docs/input-reference.md).
double value_of(const WrittenNumber& n, int shift, std::string_view whole) {
  const std::string text = n.mantissa + "e" + std::to_string(n.exponent + shift);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range || !std::isfinite(value))
    throw UnitError("'" + std::string(whole) + "': value out of range");
  if (ec != std::errc() || end != text.data() + text.size())
    throw std::logic_error("unreadable normalised number '" + text + "'");
  return value;
}

// A parsed quantity, and whether its text named a unit (a bare number did not).
struct Parsed {
  Quantity quantity;
  bool has_unit = false;
};

Parsed parse(std::string_view text) {
  const std::string_view trimmed = trim(text);
  if (trimmed.empty()) throw UnitError("empty value; expected a number with an optional unit");
  const WrittenNumber number = read_number(trimmed);
  const std::string_view unit = trim(trimmed.substr(number.length));
  if (unit.empty()) return {{value_of(number, 0, trimmed), kDimensionless}, false};
  const Factor f = UnitExpression(unit, trimmed).parse();
  return {{value_of(number, f.exponent10, trimmed), f.dimension}, true};
}

std::string with_article(const std::string& noun) {
  const bool vowel =
      !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + noun;
}

std::string describe(const Dimension& d) {
  if (d == kDimensionless) return "dimensionless number";
  return dimension_name(d) + " (" + si_unit(d) + ")";
}

}  // namespace

Quantity parse_quantity(std::string_view text) { return parse(text).quantity; }

double parse_as(std::string_view text, const Dimension& expected) {
  const Parsed p = parse(text);
  if (p.quantity.dimension == expected || !p.has_unit) return p.quantity.value;
  throw UnitError("expected " + with_article(describe(expected)) + ", got " +
                  with_article(describe(p.quantity.dimension)) + " in '" + std::string(trim(text)) +
                  "'");
}

std::string si_unit(const Dimension& d) {
  struct Named {
    Dimension dimension;
    std::string_view unit;
  };
  static constexpr std::array kNamed{
      Named{kDimensionless, "-"},
      Named{kLength, "m"},
      Named{kMass, "kg"},
      Named{kTime, "s"},
      Named{kTemperature, "K"},
      Named{kVelocity, "m/s"},
      Named{kRate, "1/s"},
      Named{kForce, "N"},
      Named{kEnergy, "J"},
      Named{kEnergy / kTime, "W"},
      Named{kPressure, "Pa"},
      Named{kDensity, "kg/m^3"},
      Named{kEnergyPerArea, "J/m^2"},
      Named{kEnergyPerAreaPerTime, "J/m^2/s"},
      Named{kSpecificHeat, "J/kg/K"},
      Named{kThermalConductivity, "W/m/K"},
      Named{kEnergy / kMass, "J/kg"},
  };
  for (const Named& n : kNamed) {
    if (n.dimension == d) return std::string(n.unit);
  }
  const std::array<std::pair<std::string_view, int>, 4> powers{
      {{"kg", d.mass}, {"m", d.length}, {"s", d.time}, {"K", d.temperature}}};
  std::string numerator;
  std::string denominator;
  for (const auto& [symbol, power] : powers) {
    if (power == 0) continue;
    const int magnitude = std::abs(power);
    const std::string factor =
        magnitude == 1 ? std::string(symbol) : fmt::format("{}^{}", symbol, magnitude);
    if (power > 0) {
      numerator += fmt::format("{}{}", numerator.empty() ? "" : "*", factor);
    } else {
      denominator += fmt::format("/{}", factor);
    }
  }
  return (numerator.empty() ? "1" : numerator) + denominator;
}

std::string dimension_name(const Dimension& d) {
  struct Named {
    Dimension dimension;
    std::string_view name;
  };
  static constexpr std::array kNamed{
      Named{kDimensionless, "dimensionless number"},
      Named{kLength, "length"},
      Named{kMass, "mass"},
      Named{kTime, "time"},
      Named{kTemperature, "temperature"},
      Named{kVelocity, "velocity"},
      Named{kRate, "rate"},
      Named{kForce, "force"},
      Named{kEnergy, "energy"},
      Named{kEnergy / kTime, "power"},
      Named{kPressure, "pressure"},
      Named{kDensity, "density"},
      Named{kEnergyPerArea, "energy per area"},
      Named{kEnergyPerAreaPerTime, "energy per area and time"},
      Named{kSpecificHeat, "specific heat"},
      Named{kThermalConductivity, "thermal conductivity"},
      Named{kEnergy / kMass, "specific energy"},
  };
  for (const Named& n : kNamed) {
    if (n.dimension == d) return std::string(n.name);
  }
  return si_unit(d);
}

namespace {

// The dimensions whose bare numbers are refused, with the unit a message suggests.
struct NeedsUnit {
  Dimension dimension;
  const char* example;
};
constexpr std::array<NeedsUnit, 3> kNeedUnits{{{kLength, "um"}, {kVelocity, "m/s"}, {kTime, "ns"}}};

}  // namespace

double parse_with_unit(const std::string& text, const Dimension& expected) {
  const double value = parse_as(text, expected);
  if (parse_quantity(text).dimension == expected) return value;
  for (const NeedsUnit& n : kNeedUnits)
    if (n.dimension == expected)
      throw UnitError("'" + text + "' has no unit: give the " + dimension_name(expected) +
                      " with its unit, e.g. '" + text + n.example + "'");
  return value;
}

}  // namespace coldspray::units
