// `coldspray impact`: one particle on a substrate from a few options. Builds the thesis'
// particle-on-cylinder case (cli/impact_case.hpp), validates it like a case file, runs it and
// prints the verdict of the impact metrics (thesis §5.2.2); or writes the case out to be edited.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/impact_case.hpp"
#include "cli/quantity_option.hpp"
#include "cli/run_report.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace coldspray::cli {

namespace {

// What names the generated case in messages that no option accounts for.
constexpr const char* kSource = "coldspray impact";

struct Options {
  std::string material, substrate_material, diameter, velocity, grid = "0.7um/0.175um";
  std::string geometry = "axisymmetric", symmetry = "quarter", bonding = "energy";
  std::string gc, gc_rate, eps_c, eps_c_rate, floor;
  std::string end_time = "80ns", shape_function = "gimp", write_case;
  RunFlags run;
};

// "CELL/SPACING": split at the '/' that a number follows, since units hold '/' too (m/s).
std::pair<double, double> parse_grid(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '/') continue;
    const std::size_t next = text.find_first_not_of(' ', i + 1);
    if (next == std::string::npos ||
        !(std::isdigit(static_cast<unsigned char>(text[next])) || text[next] == '.'))
      continue;
    return {parse_option_quantity("--grid", text.substr(0, i), units::kLength),
            parse_option_quantity("--grid", text.substr(i + 1), units::kLength)};
  }
  throw InputError("--grid", "",
                   "expected CELL/SPACING with units, e.g. 0.7um/0.175um, got '" + text + "'");
}

std::optional<double> optional_quantity(const std::string& option, const std::string& text,
                                        const units::Dimension& dimension) {
  if (text.empty()) return std::nullopt;
  return parse_option_quantity(option, text, dimension);
}

std::string shell_quoted(const std::string& text) {
  if (text.find_first_of(" '\"$*?[]{};&|<>()\\") == std::string::npos) return text;
  std::string quoted = "'";
  for (char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

// The options that shape the case, as given, for the generated file's header.
std::string command_line(const CLI::App& sub) {
  std::string command = kSource;
  for (const CLI::Option* o : sub.get_options()) {
    const std::string name = o->get_name();
    if (name == "--write-case" || name == "--out" || name == "--threads" || name == "--quiet")
      continue;
    for (const std::string& value : o->results()) command += " " + name + " " + shell_quoted(value);
  }
  return command;
}

ImpactSpec make_spec(const Options& o, const CLI::App& sub) {
  ImpactSpec spec;
  spec.material = o.material;
  spec.substrate_material = o.substrate_material;
  spec.diameter = parse_option_quantity("--diameter", o.diameter, units::kLength);
  if (!(spec.diameter > 0.0))
    throw InputError("--diameter", "", "must be > 0, got '" + o.diameter + "'");
  spec.speed = parse_option_quantity("--velocity", o.velocity, units::kVelocity);
  if (!(spec.speed > 0.0))
    throw InputError(
        "--velocity", "",
        "the impact speed towards the substrate must be > 0, got '" + o.velocity + "'");
  std::tie(spec.cell_size, spec.spacing) = parse_grid(o.grid);
  // A particle narrower than two cells has next to no points and no shape to deform; say so
  // here rather than through the seeding's "no points" message.
  if (spec.cell_size > 0.0 && spec.diameter < 2.0 * spec.cell_size)
    throw InputError("--grid", "",
                     fmt::format("the cell ({:.4g} um) must be at most half the particle "
                                 "diameter ({:.4g} um)",
                                 spec.cell_size * 1e6, spec.diameter * 1e6));
  spec.geometry =
      o.geometry == "3d" ? case_file::Geometry::ThreeD : case_file::Geometry::Axisymmetric;
  spec.symmetry = o.symmetry == "none" ? Symmetry::None : Symmetry::Quarter;
  spec.bonding = o.bonding;
  spec.critical_energy = optional_quantity("--Gc", o.gc, units::kEnergyPerArea);
  spec.critical_energy_rate =
      optional_quantity("--Gc-rate", o.gc_rate, units::kEnergyPerAreaPerTime);
  spec.critical_strain = optional_quantity("--eps-c", o.eps_c, units::kDimensionless);
  spec.critical_strain_rate = optional_quantity("--eps-c-rate", o.eps_c_rate, units::kRate);
  spec.floor = optional_quantity("--floor", o.floor, units::kDimensionless);
  spec.end_time = parse_option_quantity("--end-time", o.end_time, units::kTime);
  spec.shape_function = o.shape_function;
  spec.command = command_line(sub);
  return spec;
}

// The case file to write: the generated text, or with --set its tree after the overrides
// (which loses the comments but the header's).
std::string case_file_text(const GeneratedCase& g,
                           const std::vector<case_file::Override>& overrides) {
  if (overrides.empty()) return g.yaml;
  std::string header;
  for (std::size_t start = 0; start < g.yaml.size() && g.yaml[start] == '#';) {
    const std::size_t end = g.yaml.find('\n', start) + 1;
    header += g.yaml.substr(start, end - start);
    start = end;
  }
  header += "# Then edited by the --set options above (which the other comments predate).\n";
  return header + case_file::apply_overrides(kSource, g.yaml, overrides);
}

void write_case(const std::string& path, const std::string& text) {
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw InputError("--write-case", "", "no such folder '" + folder.string() + "'");
  io::write_atomically(path, [&](std::ostream& out) { out << text; });
}

std::string speed_text(double v) {
  return std::isnan(v) ? std::string("undefined") : fmt::format("{:.3g} m/s", v);
}

// The particle's measures and why it is or is not bonded (thesis §5.2.2: PBCP at least
// metrics.bonded_pbcp and |v_rest| at most metrics.bonded_rest_speed).
void print_verdict(const case_file::Case& c, const run::Summary& s, std::ostream& out) {
  auto body = [&s](const char* name) {
    return std::find_if(s.bodies.begin(), s.bodies.end(),
                        [name](const auto& b) { return b.name == name; });
  };
  const auto particle = body("particle"), substrate = body("substrate");
  if (particle == s.bodies.end()) return;  // renamed by --set: no verdict to give
  const metrics::ImpactMeasures& m = particle->impact;
  const double limit_pbcp = c.metrics.bonded_pbcp, limit_rest = c.metrics.bonded_rest_speed;
  std::string why = fmt::format("pbcp {:.3g} % {} {:.3g} %, ", m.pbcp,
                                m.pbcp >= limit_pbcp ? ">=" : "<", limit_pbcp);
  if (std::isnan(m.v_rest))
    why += fmt::format("no point at or below {:.3g} m/s for v_rest", c.metrics.rest_speed_limit);
  else
    why += fmt::format("|v_rest| {:.3g} m/s {} {:.3g} m/s", std::abs(m.v_rest),
                       std::abs(m.v_rest) <= limit_rest ? "<=" : ">", limit_rest);
  if (c.bonding.model == case_file::BondingModel::None) why = "bonding model none: nothing bonds";
  out << fmt::format("verdict: {} ({})\n", m.bonded ? "BONDED" : "NOT BONDED", why);
  out << fmt::format(
      "  cor {:.3g}, v_rest {}, pbcp {:.3g} %, jetted {:.3g} % of the particle's mass", m.cor,
      speed_text(m.v_rest), m.pbcp, 100.0 * m.jetted_fraction);
  if (substrate != s.bodies.end())
    out << fmt::format(", crater depth {:.3g} um", substrate->impact.crater_depth * 1e6);
  out << "\n";
  // The metrics take a body's axis to be the vertical through its centroid, which for a quarter
  // lies off the impact axis (docs/impact.md, "A quarter in 3D").
  const auto xmin = c.grid.faces.find(case_file::GridFace::XMin);
  if (c.solver.geometry == case_file::Geometry::ThreeD && xmin != c.grid.faces.end() &&
      xmin->second != case_file::FaceCondition::Free)
    out << "  (a symmetry-plane model: the jetted fraction is measured about the part's centroid, "
           "not the impact axis)\n";
}

}  // namespace

void add_impact(CLI::App& app) {
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand(
      "impact",
      "Run the thesis' single-particle test: a sphere hitting a cylindrical substrate at first "
      "contact (docs/impact.md)");
  sub->add_option("--material", opt->material, "Particle material (built-in NAME)")->required();
  sub->add_option("--substrate-material", opt->substrate_material,
                  "Substrate material (default: the particle's)");
  sub->add_option("--diameter", opt->diameter, "Particle diameter, e.g. 22um")->required();
  sub->add_option("--velocity", opt->velocity, "Impact speed, e.g. 790m/s")->required();
  sub->add_option("--grid", opt->grid, "Grid cell / point spacing (thesis §5.1.3)")
      ->capture_default_str();
  sub->add_option("--geometry", opt->geometry, "axisymmetric (r-z) or 3d")
      ->check(CLI::IsMember({"axisymmetric", "3d"}))
      ->capture_default_str();
  sub->add_option("--symmetry", opt->symmetry,
                  "3D: model one quarter (symmetry planes x = 0, y = 0) or the whole")
      ->check(CLI::IsMember({"quarter", "none"}))
      ->capture_default_str();
  sub->add_option("--bonding", opt->bonding, "Bonding model (thesis Chapter 4)")
      ->check(CLI::IsMember({"none", "strain", "energy"}))
      ->capture_default_str();
  sub->add_option("--Gc", opt->gc, "Critical adhesion energy, e.g. 1503.74J/m^2 (eq 4.16b)");
  sub->add_option("--Gc-rate", opt->gc_rate, "Critical energy rate, e.g. 2.271J/m^2/us");
  sub->add_option("--eps-c", opt->eps_c, "Critical strain (strain model, eq 4.4)");
  sub->add_option("--eps-c-rate", opt->eps_c_rate, "Critical strain rate, e.g. '8.5e8 1/s'");
  sub->add_option("--floor", opt->floor, "Lower bound of the rate factor of eqs 4.4 and 4.16b");
  sub->add_option("--end-time", opt->end_time, "Simulated time")->capture_default_str();
  sub->add_option("--shape-function", opt->shape_function, "Grid shape functions")
      ->check(CLI::IsMember({"gimp", "linear"}))
      ->capture_default_str();
  sub->add_option("--write-case", opt->write_case,
                  "Write the case file and stop (edit it, then `coldspray run` it)");
  add_run_flags(*sub, opt->run);
  sub->callback([opt, sub] {
    const ImpactSpec spec = make_spec(*opt, *sub);
    const GeneratedCase g = impact_case(spec);
    const std::vector<case_file::Override> overrides = parse_overrides(opt->run.sets);
    const case_file::Case c = case_file::load_case_text(kSource, g.yaml, g.origins, overrides);
    if (!opt->write_case.empty()) {
      write_case(opt->write_case, case_file_text(g, overrides));
      std::cout << fmt::format("wrote {} (run it with: coldspray run {})\n", opt->write_case,
                               shell_quoted(opt->write_case));
      return;
    }
    const Report report = run_and_report(c, opt->run, std::cout);
    print_verdict(c, report.summary, std::cout);
    print_results_location(report.out_dir, std::cout);
  });
}

}  // namespace coldspray::cli
