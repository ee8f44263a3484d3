#include "setups/calibration_file.hpp"

#include <fmt/format.h>

#include <array>
#include <string_view>

#include "case/case_schema.hpp"
#include "case/codecs.hpp"
#include "case/document.hpp"
#include "case/reader.hpp"
#include "core/error.hpp"
#include "setups/impact_case.hpp"
#include "setups/map_file.hpp"

namespace coldspray::setups {

namespace {

using case_file::kOptional;
using case_file::kRequired;

constexpr case_file::WholeNumber kCount{1};

constexpr std::array<std::string_view, 2> kModels{"energy", "strain"};
constexpr std::array<std::string_view, 2> kSetUps{"similar", "thesis"};
constexpr std::array<std::string_view, 2> kCalibrates{"bonding-parameters", "critical-penetration"};
constexpr std::array<std::string_view, 2> kSpacings{"linear", "log"};
constexpr std::array<std::string_view, 3> kClassifyBy{"verdict", "cor-pbcp", "cor-abp"};
constexpr std::array<std::string_view, 2> kTransforms{"identity", "log10"};

// One parameter's range; its unit is that of the parameter (eq 4.16b: J/m^2, J/m^2/s; eq 4.4:
// -, 1/s).
template <units::Dimension D>
struct AxisEntry {
  double from = 0.0, to = 0.0;
  int count = 0;
  std::string spacing = "linear";
};
template <class IO, units::Dimension D>
void fields(IO& io, AxisEntry<D>& a) {
  io.quantity("from", a.from, D, kRequired, case_file::kPositive);
  io.quantity("to", a.to, D, kRequired, case_file::kPositive);
  io.scalar("count", a.count, kCount, kRequired);
  io.scalar("spacing", a.spacing, case_file::Keywords{kSpacings}, kOptional);
  io.check(a.from < a.to, "to", "must be greater than from");
}

struct ParametersEntry {
  std::optional<AxisEntry<units::kEnergyPerArea>> critical_energy;
  std::optional<AxisEntry<units::kEnergyPerAreaPerTime>> critical_energy_rate;
  std::optional<AxisEntry<units::kDimensionless>> critical_strain;
  std::optional<AxisEntry<units::kRate>> critical_strain_rate;
};

// An optional parameter range: given when the reader filled its count, which is >= 1 once read.
template <class IO, class T>
void optional_section(IO& io, std::string_view key, std::optional<T>& value) {
  T read{};
  io.section(key, read, kOptional);
  if (read.count != 0) value = read;
}

template <class IO>
void fields(IO& io, ParametersEntry& p) {
  optional_section(io, "critical_energy", p.critical_energy);
  optional_section(io, "critical_energy_rate", p.critical_energy_rate);
  optional_section(io, "critical_strain", p.critical_strain);
  optional_section(io, "critical_strain_rate", p.critical_strain_rate);
}

struct ClassifyEntry {
  std::string by = "verdict";
  std::optional<double> cor_max, pbcp_min, abp_min;
};
template <class IO>
void fields(IO& io, ClassifyEntry& c) {
  io.scalar("by", c.by, case_file::Keywords{kClassifyBy}, kOptional);
  io.quantity("cor_max", c.cor_max, units::kDimensionless, kOptional);
  io.quantity("pbcp_min", c.pbcp_min, units::kDimensionless, kOptional,
              case_file::Range{0.0, 100.0});
  io.quantity("abp_min", c.abp_min, units::kDimensionless, kOptional, case_file::kNonNegative);
  io.check(c.by != "cor-abp" || c.abp_min.has_value(), "abp_min",
           "cor-abp needs abp_min (thesis eqs 4.8-4.9)");
  io.check(c.by != "cor-abp" || !c.pbcp_min.has_value(), "pbcp_min",
           "is for by: cor-pbcp, not cor-abp");
  io.check(c.by != "cor-pbcp" || !c.abp_min.has_value(), "abp_min",
           "is for by: cor-abp, not cor-pbcp");
  constexpr const char* kTolerance =
      "is a tolerance of by: cor-pbcp or cor-abp, not of by: verdict (the runs' own verdicts)";
  io.check(c.by != "verdict" || !c.cor_max.has_value(), "cor_max", kTolerance);
  io.check(c.by != "verdict" || !c.pbcp_min.has_value(), "pbcp_min", kTolerance);
  io.check(c.by != "verdict" || !c.abp_min.has_value(), "abp_min", kTolerance);
}

struct SizeEntry {
  double diameter = 0.0, velocity = 0.0;
  ClassifyEntry classify;
};
template <class IO>
void fields(IO& io, SizeEntry& s) {
  io.quantity("diameter", s.diameter, units::kLength, kRequired, case_file::kPositive);
  io.quantity("velocity", s.velocity, units::kVelocity, kRequired, case_file::kPositive);
  io.section("classify", s.classify, kOptional);
}

struct FitEntry {
  double ridge = 1e-3;
  int degree = 2;
};
template <class IO>
void fields(IO& io, FitEntry& f) {
  io.quantity("ridge", f.ridge, units::kDimensionless, kOptional, case_file::kNonNegative);
  io.scalar("degree", f.degree, kCount, kOptional);
  io.check(f.degree <= 4, "degree", "must be at most 4");
}

struct FileEntry {
  std::string name, material, substrate_material, model = "energy", setup = "similar";
  std::string calibrates = "bonding-parameters";
  double speed_step = 0.02;
  case_file::Geometry geometry = case_file::Geometry::Axisymmetric;
  std::optional<double> end_time;
  std::optional<double> floor, critical_penetration;
  case_file::Debond debond;
  case_file::ImpactMetrics metrics;
  std::vector<SizeEntry> sizes;
  ParametersEntry parameters;
  ClassifyEntry classify;
};
template <class IO>
void fields(IO& io, FileEntry& f) {
  io.scalar("name", f.name, case_file::Text{}, kRequired);
  io.scalar("material", f.material, case_file::Text{}, kRequired);
  io.scalar("substrate_material", f.substrate_material, case_file::Text{}, kOptional);
  io.scalar("model", f.model, case_file::Keywords{kModels}, kOptional);
  io.scalar("geometry", f.geometry, case_file::kGeometryNames, kOptional);
  io.scalar("setup", f.setup, case_file::Keywords{kSetUps}, kOptional);
  io.scalar("calibrates", f.calibrates, case_file::Keywords{kCalibrates}, kOptional);
  io.quantity("speed_step", f.speed_step, units::kDimensionless, kOptional,
              case_file::Range{0.0, 0.5, true, true});
  io.quantity("end_time", f.end_time, units::kTime, kOptional, case_file::kPositive);
  io.quantity("floor", f.floor, units::kDimensionless, kOptional, case_file::kFraction);
  io.quantity("critical_penetration", f.critical_penetration, units::kDimensionless, kOptional,
              case_file::Range{0.0, 1.0, false, true});
  io.section("debond", f.debond, kOptional);
  io.section("metrics", f.metrics, kOptional);
  io.list("sizes", f.sizes, kRequired);
  io.section("parameters", f.parameters, kOptional);  // required to calibrate them
  io.section("classify", f.classify, kOptional);
}

studies::Classification classification(const ClassifyEntry& c) {
  studies::Classification rule;
  rule.by = c.by == "cor-abp"    ? studies::Classification::By::CorAbp
            : c.by == "cor-pbcp" ? studies::Classification::By::CorPbcp
                                 : studies::Classification::By::Verdict;
  if (c.cor_max) rule.cor_max = *c.cor_max;
  if (c.pbcp_min) rule.pbcp_min = *c.pbcp_min;
  if (c.abp_min) rule.abp_min = *c.abp_min;
  return rule;
}

template <units::Dimension D>
studies::ParameterAxis axis(const char* key, const AxisEntry<D>& a) {
  return {key, units::si_unit(D), a.from, a.to, a.count, a.spacing == "log"};
}

// A key that the schema cannot read: a scalar or a list of scalars (grid), a list of two words
// (fit.transform).
std::vector<YAML::Node> scalar_items(const case_file::Document& doc, const YAML::Node& node,
                                     const std::string& key, bool allow_scalar) {
  std::vector<YAML::Node> items;
  if (allow_scalar && node.IsScalar()) return {node};
  if (!node.IsSequence() || node.size() == 0)
    throw InputError(doc.where(node), key,
                     std::string("expected ") + (allow_scalar ? "a value or " : "") +
                         "a list of values, got " + case_file::describe(node));
  for (const YAML::Node& item : node) {
    if (!item.IsScalar())
      throw InputError(doc.where(item), key, "expected a value, got " + case_file::describe(item));
    items.push_back(item);
  }
  return items;
}

// The grid configurations: one value or a list, each D/N or CELL/SPACING.
void read_grids(const case_file::Document& doc, const std::string& path, CalibrationFile& c) {
  const YAML::Node& root = doc.root();
  if (!root["grid"])
    throw InputError(path, "grid", "missing key 'grid' (e.g. D/40 or 0.7um/0.175um)");
  for (const YAML::Node& item : scalar_items(doc, root["grid"], "grid", true)) {
    try {
      parse_grid_choice(item.Scalar());
    } catch (const UnitError& e) {
      throw InputError(doc.where(item), "grid", e.what());
    }
    c.plan.grids.push_back(item.Scalar());
    c.grid_where.push_back(doc.where(item));
  }
}

// The model's two parameter ranges become x1 and x2; the other model's must not be given.
void read_parameters(const FileEntry& f, CalibrationFile& c) {
  const ParametersEntry& p = f.parameters;
  const bool energy = f.model == "energy";
  auto need = [&](bool given, const char* key) {
    if (!given)
      throw InputError(
          c.parameters_where, std::string("parameters.") + key,
          fmt::format("the {} model calibrates critical_{} and critical_{}_rate: "
                      "give a range for {}",
                      f.model, energy ? "energy" : "strain", energy ? "energy" : "strain", key));
  };
  auto refuse = [&](bool given, const char* key) {
    if (given)
      throw InputError(c.parameters_where, std::string("parameters.") + key,
                       fmt::format("is not a parameter of the {} model", f.model));
  };
  auto take = [&](const auto& r1, const char* k1, const auto& r2, const char* k2) {
    need(r1.has_value(), k1);
    need(r2.has_value(), k2);
    c.plan.x1 = axis(k1, *r1);
    c.plan.x2 = axis(k2, *r2);
  };
  auto refuse_both = [&](const auto& r1, const char* k1, const auto& r2, const char* k2) {
    refuse(r1.has_value(), k1);
    refuse(r2.has_value(), k2);
  };
  if (energy) {
    take(p.critical_energy, "critical_energy", p.critical_energy_rate, "critical_energy_rate");
    refuse_both(p.critical_strain, "critical_strain", p.critical_strain_rate,
                "critical_strain_rate");
  } else {
    take(p.critical_strain, "critical_strain", p.critical_strain_rate, "critical_strain_rate");
    refuse_both(p.critical_energy, "critical_energy", p.critical_energy_rate,
                "critical_energy_rate");
  }
}

// The logistic fit's ridge, degree and input transforms (fit.transform is a pair of words that
// may repeat, which the schema's lists refuse).
void read_fit(const case_file::Document& doc, CalibrationFile& c) {
  const YAML::Node& root = doc.root();
  FitEntry fit_entry;
  constexpr std::array<std::string_view, 1> kTransformKey{"transform"};
  if (const YAML::Node fit = root["fit"]) {
    if (!fit.IsMap())
      throw InputError(doc.where(fit), "fit", "expected a map, got " + case_file::describe(fit));
    case_file::Reader::read(doc, fit, "fit", fit_entry, false, kTransformKey);
  }
  std::array<studies::InputTransform, 2> transform = {studies::InputTransform::Identity,
                                                      studies::InputTransform::Log10};
  if (const YAML::Node fit = root["fit"]; fit && fit.IsMap() && fit["transform"]) {
    const auto items = scalar_items(doc, fit["transform"], "fit.transform", false);
    if (items.size() != 2)
      throw InputError(doc.where(fit["transform"]), "fit.transform",
                       fmt::format("expected two transforms (for {} and {}), got {}", c.plan.x1.key,
                                   c.plan.x2.key, items.size()));
    for (std::size_t k = 0; k < 2; ++k) {
      std::string word;
      try {
        case_file::Keywords{kTransforms}.parse(items[k].Scalar(), word);
      } catch (const case_file::BadValue& e) {
        throw InputError(doc.where(items[k]), "fit.transform", e.what());
      }
      transform[k] =
          word == "log10" ? studies::InputTransform::Log10 : studies::InputTransform::Identity;
    }
  }
  c.plan.fit.ridge = fit_entry.ridge;
  c.plan.fit.degree = fit_entry.degree;
  c.plan.fit.transform = transform;
}

// The sizes, each with its classification (a size's classify overrides the file's key by key),
// checked against every grid.
void read_sizes(const case_file::Document& doc, const FileEntry& f, CalibrationFile& c) {
  const YAML::Node sizes = doc.root()["sizes"];
  for (std::size_t s = 0; s < f.sizes.size(); ++s) {
    const SizeEntry& e = f.sizes[s];
    studies::CalibrationSize size;
    size.diameter = e.diameter;
    size.velocity = e.velocity;
    ClassifyEntry rule = f.classify;
    if (sizes[s]["classify"])
      case_file::Reader::read(doc, sizes[s]["classify"], fmt::format("sizes.{}.classify", s), rule,
                              /*overlay=*/true);
    size.classify = classification(rule);
    c.size_where.push_back(doc.where(sizes[s]));
    for (std::size_t g = 0; g < c.plan.grids.size(); ++g)
      check_cell_fits(parse_grid_choice(c.plan.grids[g]).cell(size.diameter), size.diameter,
                      c.grid_where[g], "grid");
    c.plan.sizes.push_back(size);
  }
  if (c.plan.sizes.empty()) throw InputError(doc.where(sizes), "sizes", "give at least one size");
}

}  // namespace

CalibrationFile read_calibration_file(const std::string& path) {
  const case_file::Document doc = read_map_file(path);
  const YAML::Node& root = doc.root();
  // grid and fit are read below: grid is a value or a list, fit.transform a pair of words.
  constexpr std::array<std::string_view, 2> kHandHeld{"grid", "fit"};
  FileEntry f;
  case_file::Reader::read(doc, root, "", f, false, kHandHeld);
  const std::array<std::string, 1> parameters_path{"parameters"};
  CalibrationFile c;
  c.path = path;
  c.file_where = path;
  c.name = f.name;
  c.material = f.material;
  c.substrate_material = f.substrate_material;
  c.model = f.model;
  c.geometry = f.geometry;
  c.setup = f.setup == "thesis" ? SetUp::Thesis : SetUp::Similar;
  c.end_time = f.end_time;
  c.verdict_window_given =
      root["metrics"] && root["metrics"].IsMap() && root["metrics"]["verdict_window"];
  c.floor = f.floor;
  c.critical_penetration = f.critical_penetration;
  c.debond = f.debond;
  c.metrics = f.metrics;
  c.parameters_where = doc.where(parameters_path);
  c.material_where = doc.where(std::array<std::string, 1>{"material"});
  c.activation = f.calibrates == "critical-penetration";
  read_grids(doc, path, c);
  if (c.activation) {
    if (root["critical_penetration"])
      throw InputError(doc.where(root["critical_penetration"]), "critical_penetration",
                       "is what calibrates: critical-penetration finds");
    if (root["parameters"] || root["fit"])
      throw InputError(doc.where(root[root["parameters"] ? "parameters" : "fit"]),
                       root["parameters"] ? "parameters" : "fit",
                       "is for calibrates: bonding-parameters; calibrates: critical-penetration "
                       "reads each size's penetration at its velocity");
  } else {
    if (!root["parameters"])
      throw InputError(path, "parameters",
                       "missing key 'parameters' (the ranges of the model's two parameters)");
    read_parameters(f, c);
    read_fit(doc, c);
  }
  read_sizes(doc, f, c);
  c.speed_step = f.speed_step;
  return c;
}

studies::ActivationPlan activation_plan(const CalibrationFile& file) {
  return {file.plan.grids, file.plan.sizes, file.speed_step};
}

namespace {

// One calibration run's impact: the file's materials, set-up and geometry for size `size_index`
// on grid `grid` at `speed`.
ImpactSpec file_impact(const CalibrationFile& file, std::size_t size_index, std::size_t grid,
                       double speed, const std::optional<double>& end_time) {
  ImpactSpec spec;
  spec.material = file.material;
  spec.substrate_material = file.substrate_material;
  spec.diameter = file.plan.sizes[size_index].diameter;
  spec.speed = speed;
  spec.setup = file.setup;
  spec.geometry = file.geometry;
  size_impact(spec, parse_grid_choice(file.plan.grids[grid]), end_time);
  spec.bonding = file.model;
  spec.floor = file.floor;
  return spec;
}

// The generated values came from the calibration file, not from options.
case_file::Case load_file_impact(const CalibrationFile& file, std::size_t size_index,
                                 std::size_t grid, GeneratedCase g) {
  for (case_file::ValueOrigin& o : g.origins) {
    if (o.origin == "--diameter" || o.origin == "--velocity")
      o.origin = file.size_where[size_index];
    else if (o.origin == "--grid")
      o.origin = file.grid_where[grid];
    else if (o.origin == "--material" || o.origin == "--substrate-material")
      o.origin = file.material_where;
    else if (o.origin.starts_with("--Gc") || o.origin.starts_with("--eps-c"))
      o.origin = file.parameters_where;
    else
      o.origin = file.file_where;
  }
  return case_file::load_case_text(file.path, g.yaml, g.origins);
}

}  // namespace

case_file::Case activation_case(const CalibrationFile& file, const studies::ActivationRun& run) {
  const studies::CalibrationSize& size = file.plan.sizes[run.size];
  // To the particle's leaving the contact, past its compression's end: nothing after it is read.
  ImpactSpec spec =
      file_impact(file, run.size, run.grid, run.speed,
                  file.end_time ? *file.end_time : kContactTimes * size.diameter / run.speed);
  spec.command = fmt::format("coldspray calibrate {} (grid {}, size {}, {:.6g} m/s)", file.path,
                             file.plan.grids[run.grid], size.label(), run.speed);
  case_file::Case c = load_file_impact(file, run.size, run.grid, impact_case(spec));
  // No bond forms before a pair is activated, so the calibration's runs have none: the bonding
  // model off moves them as the activated model moves an impact until its activation.
  c.bonding.model = case_file::BondingModel::None;
  c.metrics.verdict_extensions = 0;  // the verdict is not read
  c.bonding.debond = file.debond;
  return c;
}

case_file::Case calibration_case(const CalibrationFile& file, const studies::CalibrationRun& run) {
  const studies::CalibrationSize& size = file.plan.sizes[run.size];
  ImpactSpec spec = file_impact(file, run.size, run.grid, size.velocity, file.end_time);
  if (file.model == "energy") {
    spec.critical_energy = run.x1;
    spec.critical_energy_rate = run.x2;
  } else {
    spec.critical_strain = run.x1;
    spec.critical_strain_rate = run.x2;
  }
  spec.command = fmt::format("coldspray calibrate {} (grid {}, size {}, {} = {:.6g}, {} = {:.6g})",
                             file.path, file.plan.grids[run.grid], size.label(), file.plan.x1.key,
                             run.x1, file.plan.x2.key, run.x2);
  case_file::Case c = load_file_impact(file, run.size, run.grid, impact_case(spec));
  if (file.critical_penetration) c.bonding.critical_penetration = *file.critical_penetration;
  const double window = c.metrics.verdict_window;  // the set-up's
  c.metrics = file.metrics;  // checked by the case schema when the calibration file was read
  if (!file.verdict_window_given) c.metrics.verdict_window = window;
  c.bonding.debond = file.debond;
  return c;
}

}  // namespace coldspray::setups
