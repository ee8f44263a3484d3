// Issue 52, item 1: every quantity key of the schema reads back, bit for bit, the text any
// formatter writes for its value, bare or with a unit, from a case file and from --set; the
// whole-number keys take the same blanks and signs. "1e+3 J/m^2" used to be read as 1 J/m^2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "case/case_schema.hpp"
#include "case/load.hpp"
#include "case/reader.hpp"
#include "case/shortest_number.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::input_error;

// A quantity key of the schema: where it is (list items as 0, material names as NAME), its
// dimension, and whether it is a vector [x, y, z].
struct QuantityKey {
  std::string path;
  units::Dimension dimension;
  bool vector = false;
  friend auto operator<=>(const QuantityKey& a, const QuantityKey& b) {
    return std::tie(a.path, a.vector) <=> std::tie(b.path, b.vector);
  }
  friend bool operator==(const QuantityKey& a, const QuantityKey& b) {
    return a.path == b.path && a.vector == b.vector;
  }
};

// Walks the whole schema, every alternative of every variant and both forms of a section that
// has two, and collects its quantity keys.
class QuantityKeys {
 public:
  explicit QuantityKeys(std::set<QuantityKey>& keys, std::string path = "")
      : keys_(keys), path_(std::move(path)) {}

  template <class... Args>
  void scalar(Args&&...) {}
  template <class... Args>
  void scalars(Args&&...) {}
  template <class... Args>
  void table(Args&&...) {}
  template <class... Args>
  void check(Args&&...) {}
  template <class T, class... Rest>
  void quantity(std::string_view key, T&, units::Dimension dimension, Rest&&...) {
    keys_.insert({at(key), dimension, false});
  }
  template <class T, class... Rest>
  void vector(std::string_view key, T&, units::Dimension dimension, Rest&&...) {
    keys_.insert({at(key), dimension, true});
  }
  template <class T>
  void section(std::string_view key, T& value, Presence) {
    nested(at(key), value);
  }
  template <class T>
  void section(std::string_view key, std::optional<T>&, Presence presence) {
    T value{};
    section(key, value, presence);
  }
  template <class T, class Alternative>
  void section_either(std::string_view key, T& value, Presence, std::type_identity<Alternative>) {
    nested(at(key), value);
    Alternative alternative{};
    nested(at(key), alternative);
  }
  template <class... Ts, std::size_t N>
  void variant(std::string_view key, std::variant<Ts...>&, std::string_view,
               const std::array<std::string_view, N>&, Presence) {
    (nested(at(key), std::type_identity<Ts>{}), ...);
  }
  template <class T>
  void list(std::string_view key, std::vector<T>&, Presence) {
    T item{};
    nested(at(key) + ".0", item);
  }
  void materials(std::string_view key, std::map<std::string, materials::Material>&) {
    materials::Material m;
    nested(at(key) + ".NAME", m);
  }

 private:
  std::string at(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  template <class T>
  void nested(const std::string& path, T& value) {
    QuantityKeys inner(keys_, path);
    fields(inner, value);
  }
  template <class T>
  void nested(const std::string& path, std::type_identity<T>) {
    T value{};
    nested(path, value);
  }

  std::set<QuantityKey>& keys_;
  std::string path_;
};

std::vector<QuantityKey> schema_quantity_keys() {
  std::set<QuantityKey> keys;
  QuantityKeys walker(keys);
  Case c;
  fields(walker, c);
  return {keys.begin(), keys.end()};
}

// One key of the schema, read by the case reader from a map of that key alone: the path from
// YAML text to the double is the one every case file and --set value takes.
struct OneKey {
  std::string key;
  units::Dimension dimension;
  bool vector = false;
  double value = 0.0;
  Vec3 components = Vec3::Zero();
};

template <class IO>
void fields(IO& io, OneKey& k) {
  if (k.vector) {
    io.vector(k.key, k.components, k.dimension, kRequired);
  } else {
    io.quantity(k.key, k.value, k.dimension, kRequired);
  }
}

std::string leaf(const std::string& path) { return path.substr(path.rfind('.') + 1); }
std::string parent(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

// The value `text` gives at `key`, read from the YAML line "KEY: TEXT" (or "KEY: [TEXT, 0, 0]").
double read_key(const QuantityKey& key, const std::string& text) {
  OneKey target{leaf(key.path), key.dimension, key.vector};
  const std::string yaml = key.vector ? fmt::format("{}: [{}, 0, 0]\n", target.key, text)
                                      : fmt::format("{}: {}\n", target.key, text);
  const Document doc = Document::from_text("forms.yaml", yaml);
  Reader::read(doc, doc.root(), parent(key.path), target);
  return key.vector ? target.components[0] : target.value;
}

// The ways formatters write a double; the first group reads back to every double, the second
// (six significant digits) to the doubles that have at most six.
std::vector<std::string> exact_texts(double v) {
  char buffer[64];
  const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, v);
  const std::string to_chars_text(buffer, shortest.ptr);
  const auto scientific =
      std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::scientific);
  const std::string scientific_text(buffer, scientific.ptr);
  std::snprintf(buffer, sizeof buffer, "%+.16e", v);
  const std::string printf_text(buffer);
  std::snprintf(buffer, sizeof buffer, "%.17G", v);
  return {to_chars_text,
          scientific_text,
          fmt::format("{}", v),
          fmt::format("{:.17g}", v),
          fmt::format("{:.16e}", v),
          fmt::format("{:.16E}", v),
          printf_text,
          std::string(buffer),
          shortest_text(v)};
}

std::vector<std::string> six_digit_texts(double v) {
  char plus_e[64];
  char upper_g[64];
  std::snprintf(plus_e, sizeof plus_e, "%+e", v);
  std::snprintf(upper_g, sizeof upper_g, "%G", v);
  return {fmt::format("{:g}", v), fmt::format("{:e}", v), fmt::format("{:E}", v), plus_e, upper_g};
}

// A unit with a prefix for the key's dimension, and its power of ten; the SI unit times um/m
// (1e-6, the dimension unchanged) for dimensions that have no usual prefixed unit.
std::pair<std::string, int> prefixed_unit(const units::Dimension& d) {
  const std::pair<units::Dimension, std::pair<std::string, int>> kCommon[] = {
      {units::kLength, {"um", -6}},
      {units::kTime, {"ns", -9}},
      {units::kVelocity, {"km/s", 3}},
      {units::kPressure, {"GPa", 9}},
      {units::kEnergyPerArea, {"kJ/m^2", 3}},
      {units::kEnergyPerAreaPerTime, {"J/m^2/us", 6}},
      {units::kRate, {"1/us", 6}},
      {units::kDensity, {"g/cm^3", 3}},
      {units::kEnergy, {"nJ", -9}},
      {units::kMass, {"mg", -6}},
      {units::kSpecificHeat, {"kJ/kg/K", 3}},
  };
  for (const auto& [dimension, unit] : kCommon)
    if (dimension == d) return unit;
  if (d == units::kDimensionless) return {"um/m", -6};
  return {units::si_unit(d) + "*um/m", -6};
}

// "1.2345678901234567e-05" written for a unit of 10^shift: the exponent moved in the text.
std::string in_unit(double v, int shift) {
  const std::string text = fmt::format("{:.16e}", v);
  const std::size_t e = text.find('e');
  return fmt::format("{}E{:+04}", text.substr(0, e), std::stoi(text.substr(e + 1)) - shift);
}

::testing::AssertionResult same_double(double a, double b) {
  std::uint64_t x = 0;
  std::uint64_t y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  if (x == y) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << fmt::format("{:.17g} is not {:.17g}", a, b);
}

// Values people give and values of every magnitude a double holds (random bits, fixed seed).
std::vector<double> round_trip_values() {
  std::vector<double> values{1e12,
                             1.5e-3,
                             2.8e11,
                             0.175e-6,
                             7e-6,
                             810.0,
                             -700.0,
                             298.0,
                             1400.0,
                             2.6e10,
                             0.3,
                             1.0 / 3.0,
                             -0.0,
                             0.0,
                             1e-7,
                             123456.0,
                             5e-324,
                             2.2250738585072014e-308,
                             1.7976931348623157e308};
  std::mt19937_64 rng(52);
  while (values.size() < 60) {
    const std::uint64_t bits = rng();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  return values;
}

TEST(NumberForms, TheSchemaHasQuantityKeysOfManyDimensions) {
  const std::vector<QuantityKey> keys = schema_quantity_keys();
  EXPECT_GT(keys.size(), 80u);
  auto has = [&](const std::string& path) {
    return std::any_of(keys.begin(), keys.end(),
                       [&](const QuantityKey& k) { return k.path == path; });
  };
  for (const char* path :
       {"bonding.critical_energy", "bonding.critical_energy_rate", "bodies.0.spacing",
        "bodies.0.velocity", "bodies.0.shape.radius", "solver.end_time", "limits.max_points",
        "materials.NAME.strength.A", "materials.NAME.elastic.youngs_modulus",
        "materials.NAME.eos.c0", "grip.velocity"})
    EXPECT_TRUE(has(path)) << path;
}

TEST(NumberForms, EveryQuantityKeyReadsBackWhatFormattersWrite) {
  const std::vector<double> values = round_trip_values();
  int checked = 0;
  for (const QuantityKey& key : schema_quantity_keys()) {
    SCOPED_TRACE(key.path);
    const std::string si = key.dimension == units::kDimensionless
                               ? std::string()
                               : " " + units::si_unit(key.dimension);
    const auto [prefixed, shift] = prefixed_unit(key.dimension);
    for (const double v : values) {
      std::vector<std::string> texts = exact_texts(v);
      std::vector<std::string> with_units;
      for (const std::string& t : texts) with_units.push_back(t + si);
      texts.insert(texts.end(), with_units.begin(), with_units.end());
      if (std::abs(v) < 1e300 && std::abs(v) > 1e-300)
        texts.push_back(in_unit(v, shift) + " " + prefixed);
      for (const std::string& t : texts) {
        SCOPED_TRACE(t);
        double back = 0.0;
        ASSERT_NO_THROW(back = read_key(key, t));
        ASSERT_TRUE(same_double(back, v));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 80 * 60 * 18);
}

TEST(NumberForms, EveryQuantityKeyReadsSixDigitFormsOfSixDigitValues) {
  for (const QuantityKey& key : schema_quantity_keys()) {
    SCOPED_TRACE(key.path);
    const std::string si = key.dimension == units::kDimensionless
                               ? std::string()
                               : " " + units::si_unit(key.dimension);
    for (const double v : {1e12, -1.5e-3, 2.8e11, 1.75e-7, 810.0, 0.3, 123456.0, -0.0}) {
      for (const std::string& t : six_digit_texts(v)) {
        SCOPED_TRACE(t);
        EXPECT_TRUE(same_double(read_key(key, t), v));
        EXPECT_TRUE(same_double(read_key(key, t + si), v));
        EXPECT_TRUE(same_double(read_key(key, "'" + t + si + "'"), v));  // quoted in YAML
      }
    }
  }
}

// The reader's error names the file, line and key; the text is never read as another number.
TEST(NumberForms, MalformedNumbersAreInputErrorsAtTheirKey) {
  const QuantityKey energy{"bonding.critical_energy", units::kEnergyPerArea, false};
  const QuantityKey velocity{"bodies.0.velocity", units::kVelocity, true};
  for (const char* text : {"1e+ J/m^2", "1e++3 J/m^2", "1e3.5 J/m^2", "'1e 3 J/m^2'", "+-3",
                           "0x10 J/m^2", "1e+400 J/m^2", "1e-400", ".", "1.2.3 J/m^2"}) {
    SCOPED_TRACE(text);
    for (const QuantityKey& key : {energy, velocity}) {
      const InputError e = input_error([&] { read_key(key, text); });
      EXPECT_EQ(e.key(), key.path);
      EXPECT_TRUE(contains(e.where(), "forms.yaml:1:"));
      EXPECT_TRUE(contains(e.message(), "is not a number") ||
                  contains(e.message(), "value out of range"));
    }
  }
}

TEST(NumberForms, SetOverridesReadEveryForm) {
  const Case c = load_case(
      case_path("minimal.yaml"),
      {parse_override("bonding.critical_energy=1e+3 J/m^2"),
       parse_override("bonding.critical_energy_rate=+2.8E+05 J/m^2/us"),
       parse_override("bodies.particle.spacing=1.75e-001 um"),
       parse_override("bodies.particle.velocity=[0, +0., -8.1e+02 m/s]"),
       parse_override("solver.end_time=  8e+1ns "), parse_override("solver.cfl=.3"),
       parse_override("limits.max_points=1e+07"), parse_override("metrics.verdict_extensions=+3")});
  EXPECT_EQ(c.bonding.critical_energy, 1e3);
  EXPECT_EQ(c.bonding.critical_energy_rate, 2.8e11);
  EXPECT_EQ(c.bodies[0].spacing, 0.175e-6);
  EXPECT_EQ(c.bodies[0].velocity, Vec3(0, 0, -810));
  EXPECT_EQ(c.solver.end_time, 80e-9);
  EXPECT_EQ(c.solver.cfl, 0.3);
  EXPECT_EQ(c.limits.max_points, 1e7);
  EXPECT_EQ(c.metrics.verdict_extensions, 3);

  const InputError e = input_error([] {
    load_case(case_path("minimal.yaml"), {parse_override("bonding.critical_energy=1e++3 J/m^2")});
  });
  EXPECT_EQ(e.where(), "--set bonding.critical_energy");
  EXPECT_EQ(e.key(), "bonding.critical_energy");
  EXPECT_TRUE(contains(e.message(), "'1e++3 J/m^2' is not a number")) << e.message();
}

TEST(NumberForms, WholeNumbersTakeSignsAndBlanksAndNothingElse) {
  const WholeNumber codec{0};
  for (const auto& [text, expected] :
       {std::pair{"3", 3}, {"+3", 3}, {" 3", 3}, {"3 ", 3}, {"007", 7}, {"0", 0}}) {
    SCOPED_TRACE(text);
    int value = -1;
    codec.parse(text, value);
    EXPECT_EQ(value, expected);
  }
  for (const char* text :
       {"", "+", "-1", "+-3", "-+3", "++3", "3.0", "1e1", "0x10", "3 4", "99999999999", "three"}) {
    SCOPED_TRACE(text);
    int value = 5;
    EXPECT_THROW(codec.parse(text, value), BadValue);
    EXPECT_EQ(value, 5);
  }
}

}  // namespace
}  // namespace coldspray::case_file
