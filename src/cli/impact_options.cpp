#include "cli/impact_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "cli/quantity_option.hpp"
#include "core/error.hpp"
#include "core/units.hpp"

namespace coldspray::cli {

namespace {

std::optional<double> optional_quantity(const std::string& option, const std::string& text,
                                        const units::Dimension& dimension) {
  if (text.empty()) return std::nullopt;
  return parse_option_quantity(option, text, dimension);
}

double positive(const std::string& option, const std::string& text,
                const units::Dimension& dimension, const char* what) {
  const double value = parse_option_quantity(option, text, dimension);
  if (!(value > 0.0)) throw InputError(option, "", fmt::format("{} > 0, got '{}'", what, text));
  return value;
}

}  // namespace

void add_impact_case_options(CLI::App& sub, ImpactCaseOptions& o,
                             const std::function<void()>& particle_options) {
  sub.add_option("--solver", o.solver,
                 "mpm, or peridynamics: the PD paper's set-up (docs/impact.md)")
      ->check(CLI::IsMember({"mpm", "peridynamics"}))
      ->capture_default_str();
  sub.add_option(
      "--material", o.material,
      "Particle material (built-in NAME); required with the MPM, cu-jc for peridynamics");
  sub.add_option("--substrate-material", o.substrate_material,
                 "Substrate material (default: the particle's)");
  particle_options();
  sub.add_option("--setup", o.setup,
                 "MPM: similar (grid, substrate and times in proportion to the diameter) or "
                 "thesis (Table 5.3's substrates, 0.7um/0.175um, 80 ns); docs/impact.md")
      ->check(CLI::IsMember({"similar", "thesis"}))
      ->capture_default_str();
  sub.add_option("--resolution", o.resolution,
                 "MPM: cells across the particle's diameter, e.g. D/40 (the similar set-up's "
                 "default in r-z, D/20 in 3D; point spacing a quarter of the cell)");
  sub.add_option("--grid", o.grid,
                 "MPM: an absolute grid cell / point spacing, e.g. 0.7um/0.175um (the thesis "
                 "set-up's default, thesis §5.1.3)");
  sub.add_option("--spacing", o.spacing,
                 "Peridynamics: point spacing (default: the diameter / 50, as the PD paper)");
  sub.add_option("--geometry", o.geometry,
                 "axisymmetric (r-z) or 3d; default axisymmetric (MPM), 3d (peridynamics)")
      ->check(CLI::IsMember({"axisymmetric", "3d"}));
  sub.add_option("--symmetry", o.symmetry,
                 "3D: model one quarter (symmetry planes x = 0, y = 0) or the whole")
      ->check(CLI::IsMember({"quarter", "none"}))
      ->capture_default_str();
  sub.add_option("--contact", o.contact,
                 "Peridynamics: repulsive, lennard-jones (the PD paper's contact model 1; "
                 "the particle starts a cut-off above the substrate) or interface-bonds (its "
                 "model 2)")
      ->check(CLI::IsMember({"repulsive", "lennard-jones", "interface-bonds"}))
      ->capture_default_str();
  sub.add_option("--beta", o.beta, "Peridynamics, lennard-jones: the adhesion parameter beta");
  sub.add_option("--bonding", o.bonding,
                 "Bonding model (thesis Chapter 4); default energy (MPM), none (peridynamics)")
      ->check(CLI::IsMember({"none", "strain", "energy"}));
  sub.add_option("--Gc", o.gc, "Critical adhesion energy, e.g. 400J/m^2 (eq 4.16b)");
  sub.add_option("--Gc-rate", o.gc_rate, "Critical energy rate, e.g. 2.8e5J/m^2/us");
  sub.add_option("--eps-c", o.eps_c, "Critical strain (strain model, eq 4.4)");
  sub.add_option("--eps-c-rate", o.eps_c_rate, "Critical strain rate, e.g. '8.5e8 1/s'");
  sub.add_option("--floor", o.floor, "Lower bound of the rate factor of eqs 4.4 and 4.16b");
  sub.add_option("--end-time", o.end_time,
                 "Simulated time (default: two contact times 2 d / v and a verdict window of "
                 "20 ns x d / 14 um in the similar set-up, 80 ns in the thesis')");
  sub.add_option("--shape-function", o.shape_function, "Grid shape functions")
      ->check(CLI::IsMember({"gimp", "linear"}))
      ->capture_default_str();
  sub.add_option("--coarsening", o.coarsening,
                 "MPM: coarser substrate points away from the impact, LEVELS doublings of the "
                 "spacing, at most up to the cell (docs/impact.md); 0: uniform (default: 2 in "
                 "the similar set-up, 0 in the thesis')")
      ->check(CLI::NonNegativeNumber);
}

std::string calibration_warning(const ImpactCaseOptions& o) {
  constexpr std::string_view kCalibrated = "al-ptw";
  const std::string& substrate = o.substrate_material.empty() ? o.material : o.substrate_material;
  if (o.solver != "mpm" || !(o.bonding.empty() || o.bonding == "energy") ||
      (!o.gc.empty() && !o.gc_rate.empty()) ||
      (o.material == kCalibrated && substrate == kCalibrated))
    return "";
  return fmt::format(
      "warning: the energy bonding model's defaults (G_c, Gdot_c) were calibrated for {0} on {0}, "
      "not for {1} on {2}: its verdicts for this pair are not calibrated; give --Gc and --Gc-rate "
      "from a calibration of this pair (coldspray calibrate, docs/studies.md)",
      kCalibrated, o.material, substrate);
}

double parse_diameter(const std::string& option, const std::string& text) {
  return positive(option, text, units::kLength, "must be");
}

double parse_speed(const std::string& option, const std::string& text) {
  return positive(option, text, units::kVelocity, "the impact speed towards the substrate must be");
}

namespace {

// The PD paper's set-up (docs/impact.md): cu-jc, 3D, no bonding model, the spacing D / 50.
void peridynamics_spec(const ImpactCaseOptions& o, setups::ImpactSpec& spec) {
  spec.solver = case_file::Method::Peridynamics;
  if (spec.material.empty()) spec.material = "cu-jc";
  if (o.geometry == "axisymmetric")
    throw InputError("--geometry", "", "peridynamics runs in 3d only");
  spec.geometry = case_file::Geometry::ThreeD;
  if (!(o.bonding.empty() || o.bonding == "none"))
    throw InputError("--bonding", "",
                     "the direct bonding model is the MPM's: with --solver peridynamics, none");
  spec.bonding = "none";
  spec.contact = o.contact;
  if (!o.beta.empty()) {
    if (o.contact != "lennard-jones")
      throw InputError("--beta", "", "is the parameter of --contact lennard-jones");
    spec.beta = parse_option_quantity("--beta", o.beta, units::kDimensionless);
    if (!(*spec.beta > 0.0 && *spec.beta < 1.0))
      throw InputError("--beta", "", fmt::format("must be in (0, 1), got '{}'", o.beta));
  }
  spec.spacing = o.spacing.empty() ? spec.diameter / setups::kPeridynamicsPointsAcross
                                   : positive("--spacing", o.spacing, units::kLength, "must be");
  if (spec.spacing > spec.diameter / 4.0)
    throw InputError(
        "--spacing", "",
        fmt::format("the spacing ({:.4g} um) must be at most a quarter of the particle "
                    "diameter ({:.4g} um), for a family across it",
                    spec.spacing * 1e6, spec.diameter * 1e6));
  spec.cell_size = 0.0;
}

}  // namespace

setups::ImpactSpec impact_spec(const ImpactCaseOptions& o, double diameter, double speed,
                               const std::string& command) {
  setups::ImpactSpec spec;
  spec.material = o.material;
  spec.substrate_material = o.substrate_material;
  spec.diameter = diameter;
  spec.speed = speed;
  spec.symmetry = o.symmetry == "none" ? setups::Symmetry::None : setups::Symmetry::Quarter;
  if (o.solver == "peridynamics") {
    if (o.coarsening)
      throw InputError("--coarsening", "",
                       "is the MPM's option: peridynamic families need one spacing");
    for (const auto& [option, given] :
         {std::pair{"--grid", !o.grid.empty()}, std::pair{"--resolution", !o.resolution.empty()},
          std::pair{"--setup", o.setup != "similar"}})
      if (given)
        throw InputError(
            option, "",
            "is the MPM's option: peridynamics takes --spacing (the PD paper's set-up)");
    peridynamics_spec(o, spec);
  } else {
    if (spec.material.empty())
      throw InputError("--material", "", "required with --solver mpm (a built-in material NAME)");
    if (!o.spacing.empty())
      throw InputError("--spacing", "",
                       "is peridynamics' option: the MPM takes --grid CELL/SPACING");
    spec.setup = o.setup == "thesis" ? setups::SetUp::Thesis : setups::SetUp::Similar;
    if (!o.grid.empty() && !o.resolution.empty())
      throw InputError("--resolution", "",
                       "give --resolution D/N or --grid CELL/SPACING, not both");
    const char* option = o.grid.empty() ? "--resolution" : "--grid";
    std::optional<setups::GridChoice> grid;
    try {
      if (!o.resolution.empty()) {
        grid = setups::parse_grid_choice(o.resolution);
        if (grid->cells_per_diameter == 0.0)
          throw UnitError("expected D/N, e.g. D/40 (an absolute grid is --grid), got '" +
                          o.resolution + "'");
      } else if (!o.grid.empty()) {
        grid = setups::parse_grid_choice(o.grid);
      }
    } catch (const UnitError& e) {
      throw InputError(option, "", e.what());
    }
    spec.geometry =
        o.geometry == "3d" ? case_file::Geometry::ThreeD : case_file::Geometry::Axisymmetric;
    setups::size_impact(spec, grid, optional_quantity("--end-time", o.end_time, units::kTime));
    setups::check_cell_fits(spec.cell_size, spec.diameter, option);
    if (o.contact != "repulsive" || !o.beta.empty())
      throw InputError(
          o.beta.empty() ? "--contact" : "--beta", "",
          "is peridynamics' option: the MPM's grid contact has no force law to choose");
    spec.bonding = o.bonding.empty() ? "energy" : o.bonding;
  }
  spec.critical_energy = optional_quantity("--Gc", o.gc, units::kEnergyPerArea);
  spec.critical_energy_rate =
      optional_quantity("--Gc-rate", o.gc_rate, units::kEnergyPerAreaPerTime);
  spec.critical_strain = optional_quantity("--eps-c", o.eps_c, units::kDimensionless);
  spec.critical_strain_rate = optional_quantity("--eps-c-rate", o.eps_c_rate, units::kRate);
  spec.floor = optional_quantity("--floor", o.floor, units::kDimensionless);
  if (o.solver == "peridynamics")
    spec.end_time =
        o.end_time.empty() ? 80e-9 : parse_option_quantity("--end-time", o.end_time, units::kTime);
  spec.shape_function = o.shape_function;
  if (o.coarsening) spec.coarsening = *o.coarsening;
  spec.command = command;
  return spec;
}

std::string shell_quoted(const std::string& text) {
  if (text.find_first_of(" '\"$*?[]{};&|<>()\\") == std::string::npos) return text;
  std::string quoted = "'";
  for (char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

std::string command_line(const std::string& source, const CLI::App& sub,
                         std::initializer_list<std::string_view> skip) {
  std::string command = source;
  for (const CLI::Option* o : sub.get_options()) {
    const std::string name = o->get_name();
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    for (const std::string& value : o->results()) command += " " + name + " " + shell_quoted(value);
  }
  return command;
}

}  // namespace coldspray::cli
