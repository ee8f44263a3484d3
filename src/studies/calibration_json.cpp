#include "studies/calibration_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace coldspray::studies {
namespace {

using Json = nlohmann::ordered_json;

// calibration.json has always had its keys in alphabetical order (it was written from
// nlohmann::json's sorted map): the fields below are declared in that order, and the objects
// keyed by the plan's own names (its parameters' keys, its sizes' labels) go through that map.
Json sorted(const Json& j) { return Json(nlohmann::json(j)); }

Json or_null(const std::string& s) { return s.empty() ? Json() : Json(s); }

// A study's file: its plan, its result per grid and its name.
template <class Plan, class Result>
struct Study {
  const Plan& plan;
  const std::vector<Result>& results;
  const std::string& name;
};

// One grid's result, with the plan it is of.
template <class Plan, class Result>
struct GridOf {
  const Plan& plan;
  const Result& result;
};

// The study's grids, each written from `fields`.
template <class Plan, class Result>
Json grids_json(const io::OutputFields<GridOf<Plan, Result>>& fields,
                const Study<Plan, Result>& study) {
  Json grids = Json::array();
  for (const Result& r : study.results) grids.push_back(io::write_fields(fields, {study.plan, r}));
  return grids;
}

using Report = Study<CalibrationPlan, GridResult>;
using GridEntry = GridOf<CalibrationPlan, GridResult>;

// One size of a grid: its plan and its analysis.
struct SizeEntry {
  const CalibrationSize& size;
  const SizeResult& result;
};

// A point of the parameter plane, keyed by the parameters' keys.
struct Point {
  const CalibrationPlan& plan;
  std::array<double, 2> x;
};

// The two sizes' closest approach, with the plan that names its points' keys.
struct Closest {
  const CalibrationPlan& plan;
  const ClosestApproach& approach;
};

const io::OutputFields<ParameterAxis>& axis_fields() {
  static const io::OutputFields<ParameterAxis> fields = {
      {"count", "-", [](const auto& a) { return Json(a.count); }},
      {"from", "<unit>", [](const auto& a) { return Json(a.from); }},
      {"key", "-", [](const auto& a) { return Json(a.key); }},
      {"spacing", "-", [](const auto& a) { return Json(a.log ? "log" : "linear"); }},
      {"to", "<unit>", [](const auto& a) { return Json(a.to); }},
      {"unit", "-", [](const auto& a) { return Json(a.unit); }},
      {"values", "<unit>", [](const auto& a) { return Json(parameter_values(a)); }}};
  return fields;
}

const io::OutputFields<Report>& parameters_fields() {
  static const io::OutputFields<Report> fields = {
      {"x1", "-", [](const auto& r) { return io::write_fields(axis_fields(), r.plan.x1); }},
      {"x2", "-", [](const auto& r) { return io::write_fields(axis_fields(), r.plan.x2); }}};
  return fields;
}

const io::OutputFields<LogisticOptions>& fit_options_fields() {
  static const io::OutputFields<LogisticOptions> fields = {
      {"degree", "-", [](const auto& o) { return Json(o.degree); }},
      {"ridge", "-", [](const auto& o) { return Json(o.ridge); }}};
  return fields;
}

const io::OutputFields<Point>& point_fields() {
  static const io::OutputFields<Point> fields = {
      {"<x1 key>", "<unit>", [](const auto& p) { return Json(p.x[0]); },
       [](const auto& p) { return p.plan.x1.key; }},
      {"<x2 key>", "<unit>", [](const auto& p) { return Json(p.x[1]); },
       [](const auto& p) { return p.plan.x2.key; }}};
  return fields;
}

Json point_json(const CalibrationPlan& plan, const std::array<double, 2>& x) {
  return sorted(io::write_fields(point_fields(), Point{plan, x}));
}

Json point_json(const CalibrationPlan& plan, const Eigen::Vector2d& x) {
  return point_json(plan, std::array<double, 2>{x[0], x[1]});
}

const io::OutputFields<Closest>& closest_fields() {
  static const io::OutputFields<Closest> fields = {
      {"distance", "-", [](const auto& c) { return Json(c.approach.distance); }},
      {"on_<first size>", "-", [](const auto& c) { return point_json(c.plan, c.approach.on_a); },
       [](const auto& c) { return "on_" + c.plan.sizes[0].label(); }},
      {"on_<second size>", "-", [](const auto& c) { return point_json(c.plan, c.approach.on_b); },
       [](const auto& c) { return "on_" + c.plan.sizes[1].label(); }}};
  return fields;
}

const io::OutputFields<Classification>& classify_fields() {
  using By = Classification::By;
  static const io::OutputFields<Classification> fields = {
      {"abp_min", "-",
       [](const auto& c) { return c.by == By::CorAbp ? Json(c.abp_min) : io::absent_field(); }},
      {"by", "-",
       [](const auto& c) {
         return Json(c.by == By::CorPbcp ? "cor-pbcp" : c.by == By::CorAbp ? "cor-abp" : "verdict");
       }},
      {"cor_max", "-",
       [](const auto& c) { return c.by != By::Verdict ? Json(c.cor_max) : io::absent_field(); }},
      {"pbcp_min", "%",
       [](const auto& c) { return c.by == By::CorPbcp ? Json(c.pbcp_min) : io::absent_field(); }}};
  return fields;
}

Json vector_json(const Eigen::VectorXd& v) {
  return Json(std::vector<double>(v.data(), v.data() + v.size()));
}

const char* transform_name(InputTransform t) {
  return t == InputTransform::Log10 ? "log10" : "identity";
}

const io::OutputFields<LogisticFit>& logistic_fit_fields() {
  static const io::OutputFields<LogisticFit> fields = {
      {"accuracy", "-", [](const auto& f) { return Json(f.accuracy); }},
      {"converged", "-", [](const auto& f) { return Json(f.converged); }},
      {"cost", "-", [](const auto& f) { return Json(f.cost); }},
      {"degree", "-", [](const auto& f) { return Json(f.degree); }},
      {"iterations", "-", [](const auto& f) { return Json(f.iterations); }},
      // Of the transformed inputs: the parameter in its unit, or its log10.
      {"mean", "<unit> or -",
       [](const auto& f) {
         return Json::array({f.scaling.mean[0], f.scaling.mean[1]});
       }},
      {"scale", "<unit> or -",
       [](const auto& f) {
         return Json::array({f.scaling.scale[0], f.scaling.scale[1]});
       }},
      {"theta", "-", [](const auto& f) { return vector_json(f.theta); }},
      {"theta_unstandardized", "-",
       [](const auto& f) { return vector_json(f.theta_unstandardized()); }},
      {"transform", "-", [](const auto& f) {
         return Json::array(
             {transform_name(f.scaling.transform[0]), transform_name(f.scaling.transform[1])});
       }}};
  return fields;
}

const io::OutputFields<SizeEntry>& size_fields() {
  static const io::OutputFields<SizeEntry> fields = {
      {"bonded", "-", [](const auto& s) { return Json(s.result.bonded); }},
      {"boundary_csv", "-", [](const auto& s) { return or_null(s.result.boundary_file); }},
      {"classify", "-",
       [](const auto& s) { return io::write_fields(classify_fields(), s.size.classify); }},
      {"diagnosis", "-", [](const auto& s) { return or_null(s.result.diagnosis); }},
      {"diameter_um", "um", [](const auto& s) { return Json(s.size.diameter * 1e6); }},
      {"failed", "-", [](const auto& s) { return Json(s.result.failed); }},
      {"fit", "-",
       [](const auto& s) {
         return s.result.fit ? io::write_fields(logistic_fit_fields(), *s.result.fit) : Json();
       }},
      {"not_bonded", "-", [](const auto& s) { return Json(s.result.not_bonded); }},
      {"runs", "-", [](const auto& s) { return Json(s.result.runs); }},
      {"size", "-", [](const auto& s) { return Json(s.size.label()); }},
      {"undecided", "-", [](const auto& s) { return Json(s.result.undecided); }},
      {"velocity_ms", "m/s", [](const auto& s) { return Json(s.size.velocity); }}};
  return fields;
}

Json calibrated_by(const GridResult& r) {
  return !r.calibrated             ? Json()
         : r.intersections.empty() ? Json("closest approach")
                                   : Json("intersection");
}

Json intersections_json(const GridEntry& g) {
  Json points = Json::array();
  for (const auto& p : g.result.intersections) points.push_back(point_json(g.plan, p));
  return points;
}

Json sizes_json(const GridEntry& g) {
  Json sizes = Json::array();
  for (std::size_t s = 0; s < g.plan.sizes.size(); ++s)
    sizes.push_back(io::write_fields(size_fields(), {g.plan.sizes[s], g.result.sizes[s]}));
  return sizes;
}

const io::OutputFields<GridEntry>& grid_fields() {
  static const io::OutputFields<GridEntry> fields = {
      {"calibrated", "-",
       [](const auto& g) {
         return g.result.calibrated ? point_json(g.plan, *g.result.calibrated) : Json();
       }},
      {"calibrated_by", "-", [](const auto& g) { return calibrated_by(g.result); }},
      {"closest_approach", "-",
       [](const auto& g) {
         return g.result.closest
                    ? sorted(io::write_fields(closest_fields(), {g.plan, *g.result.closest}))
                    : Json();
       }},
      {"diagnosis", "-", [](const auto& g) { return or_null(g.result.diagnosis); }},
      {"grid", "-", [](const auto& g) { return Json(g.result.grid); }},
      {"intersections", "-", intersections_json},
      {"sizes", "-", sizes_json}};
  return fields;
}

const io::OutputFields<Report>& calibration_fields() {
  static const io::OutputFields<Report> fields = {
      {"fit_options", "-",
       [](const auto& r) { return io::write_fields(fit_options_fields(), r.plan.fit); }},
      {"grids", "-", [](const auto& r) { return grids_json(grid_fields(), r); }},
      {"name", "-", [](const auto& r) { return Json(r.name); }},
      {"parameters", "-", [](const auto& r) { return io::write_fields(parameters_fields(), r); }}};
  return fields;
}

// The activation calibration's calibration.json: its keys alphabetical too.
using ActivationReport = Study<ActivationPlan, ActivationGridResult>;
using ActivationGrid = GridOf<ActivationPlan, ActivationGridResult>;

// One size's penetration law and the vcrit the calibrated delta predicts for it.
struct ActivationSize {
  const CalibrationSize& size;
  const PenetrationLaw& law;
  double predicted;  // m/s, NaN without a calibration
};

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(); }

const io::OutputFields<ActivationSize>& activation_size_fields() {
  static const io::OutputFields<ActivationSize> fields = {
      {"diameter_um", "um", [](const auto& s) { return Json(s.size.diameter * 1e6); }},
      {"error", "-",
       [](const auto& s) { return finite_or_null(s.predicted / s.size.velocity - 1.0); }},
      {"exponent", "-", [](const auto& s) { return finite_or_null(s.law.exponent); }},
      {"penetration", "m", [](const auto& s) { return finite_or_null(s.law.at_velocity); }},
      {"predicted_vcrit_ms", "m/s", [](const auto& s) { return finite_or_null(s.predicted); }},
      {"velocity_ms", "m/s", [](const auto& s) { return Json(s.size.velocity); }}};
  return fields;
}

Json activation_sizes_json(const ActivationGrid& g) {
  Json sizes = Json::array();
  for (std::size_t s = 0; s < g.plan.sizes.size(); ++s) {
    const double predicted = s < g.result.predicted.size() ? g.result.predicted[s] : NAN;
    sizes.push_back(
        io::write_fields(activation_size_fields(), {g.plan.sizes[s], g.result.laws[s], predicted}));
  }
  return sizes;
}

const io::OutputFields<ActivationGrid>& activation_grid_fields() {
  static const io::OutputFields<ActivationGrid> fields = {
      {"critical_penetration", "m",
       [](const auto& g) {
         return g.result.critical_penetration ? Json(*g.result.critical_penetration) : Json();
       }},
      {"diagnosis", "-", [](const auto& g) { return Json(g.result.diagnosis); }},
      {"grid", "-", [](const auto& g) { return Json(g.result.grid); }},
      {"sizes", "-", activation_sizes_json}};
  return fields;
}

const io::OutputFields<ActivationReport>& activation_fields() {
  static const io::OutputFields<ActivationReport> fields = {
      {"calibrates", "-", [](const auto&) { return Json("bonding.critical_penetration"); }},
      {"grids", "-", [](const auto& r) { return grids_json(activation_grid_fields(), r); }},
      {"name", "-", [](const auto& r) { return Json(r.name); }},
      {"step", "-", [](const auto& r) { return Json(r.plan.step); }}};
  return fields;
}

}  // namespace

void write_calibration_json(const CalibrationPlan& plan, const std::vector<GridResult>& results,
                            const std::filesystem::path& out_dir, const std::string& name) {
  io::write_fields_file(out_dir / "calibration.json", calibration_fields(),
                        Report{plan, results, name});
}

io::FieldUnits calibration_field_units() {
  io::FieldUnits out;
  io::append_field_units(calibration_fields(), "", out);
  io::append_field_units(fit_options_fields(), "fit_options.", out);
  io::append_field_units(grid_fields(), "grids[].", out);
  io::append_field_units(point_fields(), "grids[].calibrated.", out);
  io::append_field_units(closest_fields(), "grids[].closest_approach.", out);
  io::append_field_units(point_fields(), "grids[].closest_approach.on_<size>.", out);
  io::append_field_units(point_fields(), "grids[].intersections[].", out);
  io::append_field_units(size_fields(), "grids[].sizes[].", out);
  io::append_field_units(classify_fields(), "grids[].sizes[].classify.", out);
  io::append_field_units(logistic_fit_fields(), "grids[].sizes[].fit.", out);
  io::append_field_units(parameters_fields(), "parameters.", out);
  io::append_field_units(axis_fields(), "parameters.<x>.", out);
  return out;
}

void write_activation_json(const ActivationPlan& plan,
                           const std::vector<ActivationGridResult>& results,
                           const std::filesystem::path& out_dir, const std::string& name) {
  io::write_fields_file(out_dir / "calibration.json", activation_fields(),
                        ActivationReport{plan, results, name});
}

io::FieldUnits activation_field_units() {
  io::FieldUnits out;
  io::append_field_units(activation_fields(), "", out);
  io::append_field_units(activation_grid_fields(), "grids[].", out);
  io::append_field_units(activation_size_fields(), "grids[].sizes[].", out);
  return out;
}

}  // namespace coldspray::studies
