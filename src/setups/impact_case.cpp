#include "setups/impact_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iterator>
#include <string_view>

#include "case/grid_domain.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "setups/case_text.hpp"

namespace coldspray::setups {

namespace {

constexpr double kUm = 1e-6;

// Thesis Table 5.3: particle diameter -> substrate cylinder diameter, um (all 10 um high).
constexpr std::array<std::array<double, 2>, 5> kTable53{
    {{14.0, 30.0}, {18.0, 36.0}, {22.0, 44.0}, {26.0, 46.0}, {30.0, 50.0}}};
constexpr double kTableHeightUm = 10.0;

// Up to the next 0.1 um, so that generated sizes print as short decimals; the small tolerance
// keeps sizes that already are on a 0.1 um step (30 um) where they are.
double round_up_um(double um) { return std::ceil(um * 10.0 - 1e-6) / 10.0; }

double table_diameter_um(double d) {
  const auto& first = kTable53.front();
  const auto& last = kTable53.back();
  if (d <= first[0]) return first[1] / first[0] * d;
  if (d > last[0]) return 2.0 * d;
  const auto upper =
      std::find_if(kTable53.begin(), kTable53.end(), [d](const auto& row) { return row[0] >= d; });
  const auto& hi = *upper;
  const auto& lo = *std::prev(upper);
  return lo[1] + (hi[1] - lo[1]) * (d - lo[0]) / (hi[0] - lo[0]);
}

// The grid of a 3D quarter model: from the symmetry planes x = 0 and y = 0 to the bodies'
// bounds plus the margin the solver adds when it places the grid itself (case/grid_domain.hpp), on
// multiples of the cell size.
struct QuarterGrid {
  case_file::Vec3 min, max;
};
QuarterGrid quarter_grid(double particle_diameter, const SubstrateSize& substrate, double cell) {
  const case_file::Vec3 lo(0.0, 0.0, -substrate.height);
  const case_file::Vec3 hi(0.5 * substrate.diameter, 0.5 * substrate.diameter, particle_diameter);
  QuarterGrid g;
  for (int d = 0; d < 3; ++d) {
    const double margin = std::max(case_file::kGridMarginFraction * (hi[d] - lo[d]),
                                   case_file::kGridMarginMinCells * cell);
    // The tolerance keeps a bound that is a whole number of cells (26 um) from gaining one to
    // rounding (2.6e-5 / 1e-6 = 26.000000000000004), as the solver's own placement does.
    g.min[d] = d < 2 ? 0.0 : std::floor((lo[d] - margin) / cell + 1e-9) * cell;
    g.max[d] = std::ceil((hi[d] + margin) / cell - 1e-9) * cell;
  }
  return g;
}

// The bodies: the particle `lift` above z = 0 at t = 0 (0: touching it), moving down at the
// spec's speed, and the substrate cylinder below z = 0, both at the spec's spacing and 298 K; the
// solver's boundary keys of the substrate follow.
void append_bodies(std::string& y, const ImpactSpec& spec, const std::string& substrate_material,
                   double substrate_radius, double substrate_height, double lift = 0.0) {
  const double radius = 0.5 * spec.diameter;
  auto line = [&y](const std::string& text) { y += text + "\n"; };
  line("bodies:");
  line("  - name: particle");
  line("    material: " + yaml_scalar(spec.material));
  line(fmt::format("    shape: {{type: sphere, center: [0, 0, {}], radius: {}}}", um(radius + lift),
                   um(radius)));
  line("    spacing: " + um(spec.spacing));
  line(fmt::format("    velocity: [0, 0, -{} m/s]", number(spec.speed)));
  line("    temperature: 298 K");
  line("  - name: substrate");
  line("    material: " + yaml_scalar(substrate_material));
  line(
      fmt::format("    shape: {{type: cylinder, base_center: [0, 0, -{}], radius: {}, height: {}}}",
                  um(substrate_height), um(substrate_radius), um(substrate_height)));
  line("    spacing: " + um(spec.spacing));
  line("    temperature: 298 K");
}

// The substrate's coarsened seeding (docs/mpm.md, "Coarsened seeding"), fine near the impact
// (impact_case.hpp: kCoarseningFineRadius, kCoarseningFineDepth).

void append_coarsening(std::string& y, const ImpactSpec& spec, const SubstrateSize& substrate) {
  const double depth = std::min(kCoarseningFineDepth * spec.diameter, substrate.height);
  y += fmt::format(
      "    coarsening: {{levels: {}, fine: {{type: cylinder, base_center: [0, 0, -{}], radius: "
      "{}, height: {}}}}}   # coarser points away from the impact (docs/mpm.md)\n",
      spec.coarsening, um(depth), um(kCoarseningFineRadius * spec.diameter), um(depth));
}

// With contact model 1 the particle starts where its nearest points are a cut-off R_c (the
// schema's default r0 and cut-off) from the substrate's: a whole number of spacings above
// touching, so that the lattices stay aligned, and no pair closer than the potential's
// equilibrium distance at t = 0 (pd/setup.cpp refuses that).
double lennard_jones_lift(const ImpactSpec& spec) {
  if (spec.contact != "lennard-jones") return 0.0;
  const case_file::PeridynamicsContact defaults;
  const double reach = defaults.cutoff * defaults.r0 * spec.spacing;
  // Touching, the nearest points are one spacing apart; each spacing of lift adds one.
  return (std::ceil(reach / spec.spacing - 1e-9) - 1.0) * spec.spacing;
}

// The PD paper's set-up ("Simulation Setup", Fig 2): the particle on a cylinder of radius and
// height four particle radii, bottom fixed, side restrained in x and y, from first contact, a
// quarter by symmetry unless the whole is asked for; repulsive contact, no bonding model.
GeneratedCase peridynamics_impact_case(const ImpactSpec& spec) {
  const std::string substrate_material =
      spec.substrate_material.empty() ? spec.material : spec.substrate_material;
  const bool quarter = spec.symmetry == Symmetry::Quarter;
  const double substrate = 2.0 * spec.diameter;  // four particle radii
  GeneratedCase g;
  g.name = folder_safe(fmt::format(
      "impact-pd-{}{}-{}um-{}{}", spec.material,
      substrate_material == spec.material ? "" : "-on-" + substrate_material,
      short_number(spec.diameter / kUm), short_number(spec.speed), quarter ? "" : "-whole"));
  std::string y;
  auto line = [&y](const std::string& text) { y += text + "\n"; };
  line("# Generated by: " + one_line(spec.command));
  append_comment(
      y, fmt::format("A {} um particle of {} hits a substrate of {} at {} m/s in correspondence "
                     "peridynamics (docs/pd.md), as the PD paper's Fig 2: the substrate cylinder's "
                     "radius and height are four particle radii ({}), its bottom is fixed and its "
                     "side restrained in x and y; the particle {} at t = 0; {} points across the "
                     "particle.",
                     short_number(spec.diameter / kUm), spec.material, substrate_material,
                     short_number(spec.speed), um(substrate),
                     spec.contact == "lennard-jones"
                         ? "starts " + um(lennard_jones_lift(spec)) +
                               " above the substrate's top face z = 0, where contact model 1's "
                               "cut-off first reaches it"
                         : std::string("touches the substrate's top face z = 0"),
                     short_number(spec.diameter / spec.spacing)));
  if (quarter)
    append_comment(y,
                   "One quarter is modelled: x = 0 and y = 0 are symmetry planes, across which "
                   "the solver mirrors the points near them.");
  line("name: " + g.name);
  line("description: " +
       yaml_scalar(fmt::format(
           "{} {} um sphere at {} m/s on a {} x {} {} cylinder, peridynamics, {}", spec.material,
           short_number(spec.diameter / kUm), short_number(spec.speed), um(2.0 * substrate),
           um(substrate), substrate_material, quarter ? "one quarter" : "whole")));
  append_bodies(y, spec, substrate_material, substrate, substrate, lennard_jones_lift(spec));
  line("    fixed: [bottom]");
  line("    roller: [side]   # restrained in x and y (the PD paper)");
  if (quarter) line("symmetry: {x: 0 um, y: 0 um}");
  if (spec.contact == "lennard-jones") {
    line("contact:");
    line("  peridynamics:");
    line("    model: lennard-jones   # the PD paper's contact model 1 (eqs 15-22)");
    if (spec.beta) line("    beta: " + number(*spec.beta));
  }
  if (spec.contact == "interface-bonds") {
    line("contact:");
    line("  peridynamics:");
    line("    model: interface-bonds   # the PD paper's contact model 2 (eqs 23-25)");
  }
  line("solver:");
  line("  method: peridynamics");
  line(fmt::format("  end_time: {} ns", number(spec.end_time * 1e9)));
  line("output:");
  line("  history_interval: 0.5 ns");
  line("  snapshot_interval: 10 ns");
  g.yaml = std::move(y);
  g.origins = {{"bodies.particle.material", spec.material.empty() ? "--solver" : "--material"},
               {"bodies.substrate.material",
                spec.substrate_material.empty() ? "--material" : "--substrate-material"},
               {"bodies.particle.shape", "--diameter"},
               {"bodies.substrate.shape", "--diameter"},
               {"bodies.particle.velocity", "--velocity"},
               {"bodies.particle.spacing", "--spacing"},
               {"bodies.substrate.spacing", "--spacing"},
               {"solver.end_time", "--end-time"}};
  return g;
}

}  // namespace

double GridChoice::cell(double diameter) const {
  return cells_per_diameter > 0.0 ? diameter / cells_per_diameter : cell_size;
}

double GridChoice::point_spacing(double diameter) const {
  return cells_per_diameter > 0.0 ? cell(diameter) / kSpacingsPerCell : spacing;
}

std::string GridChoice::text() const {
  if (cells_per_diameter > 0.0) return "D/" + number(cells_per_diameter);
  return um(cell_size) + "/" + um(spacing);
}

std::pair<double, double> parse_grid(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '/') continue;
    const std::size_t next = text.find_first_not_of(' ', i + 1);
    if (next == std::string::npos ||
        !(std::isdigit(static_cast<unsigned char>(text[next])) || text[next] == '.'))
      continue;
    const double cell = units::parse_with_unit(text.substr(0, i), units::kLength);
    const double spacing = units::parse_with_unit(text.substr(i + 1), units::kLength);
    // A deposit file's grid: 0um/0um passed its reader and was refused only in the generated
    // case, at a key of it ('bodies.p1.spacing') and at the file's particles, not its grid.
    if (!(cell > 0.0) || !(spacing > 0.0))
      throw UnitError("the cell and the spacing must be > 0, got '" + text + "'");
    return {cell, spacing};
  }
  throw UnitError("expected CELL/SPACING with units, e.g. 0.7um/0.175um, got '" + text + "'");
}

GridChoice parse_grid_choice(const std::string& text) {
  const std::size_t first = text.find_first_not_of(' ');
  if (first == std::string::npos || (text[first] != 'D' && text[first] != 'd')) {
    const auto [cell, spacing] = parse_grid(text);
    return {0.0, cell, spacing};
  }
  const std::size_t slash = text.find_first_not_of(' ', first + 1);
  if (slash == std::string::npos || text[slash] != '/')
    throw UnitError("expected D/N (N cells across the particle's diameter), got '" + text + "'");
  const double cells = units::parse_as(text.substr(slash + 1), units::kDimensionless);
  if (!(cells >= 2.0) ||
      units::parse_quantity(text.substr(slash + 1)).dimension != units::kDimensionless)
    throw UnitError("D/N needs a number of cells N >= 2, got '" + text + "'");
  return {cells};
}

SubstrateSize substrate_size(double particle_diameter, SetUp setup) {
  if (setup == SetUp::Similar)
    return {kSimilarSubstrateDiameter * particle_diameter,
            kSimilarSubstrateHeight * particle_diameter};
  // To the picometre: "30um" is 30.000000000000004 um after the division, which must still be
  // the table's 30 um rather than a size beyond it.
  const double d = std::round(particle_diameter / kUm * 1e6) / 1e6;
  return {round_up_um(table_diameter_um(d)) * kUm,
          round_up_um(std::max(kTableHeightUm, d / 3.0)) * kUm};
}

void size_impact(ImpactSpec& spec, const std::optional<GridChoice>& grid,
                 const std::optional<double>& end_time) {
  const bool similar = spec.setup == SetUp::Similar;
  // The thesis' recommended 0.7/0.175 um (§5.1.3-5.1.4) for its set-up.
  const GridChoice chosen = grid      ? *grid
                            : similar ? GridChoice{spec.geometry == case_file::Geometry::ThreeD
                                                       ? kDefaultCellsPerDiameter3d
                                                       : kDefaultCellsPerDiameter}
                                      : GridChoice{0.0, 0.7e-6, 0.175e-6};
  spec.cell_size = chosen.cell(spec.diameter);
  spec.spacing = chosen.point_spacing(spec.diameter);
  // As many doublings of the spacing as fit in the cell, up to kSimilarCoarsening.
  spec.coarsening = 0;
  while (similar && spec.coarsening < kSimilarCoarsening &&
         std::ldexp(spec.spacing, spec.coarsening + 1) <= spec.cell_size * (1 + 1e-12))
    ++spec.coarsening;
  // The thesis' 14 um times (§5.2.2), scaled with d in the similar set-up, where the run ends a
  // verdict window after the particle has left the contact.
  const double scale = similar ? spec.diameter / kThesisTimesDiameter : 1.0;
  spec.verdict_window = similar ? 20e-9 * scale : 0.0;
  spec.end_time = end_time  ? *end_time
                  : similar ? spec.verdict_window + kContactTimes * spec.diameter / spec.speed
                            : 80e-9;
  spec.history_interval = 0.5e-9 * scale;
  spec.snapshot_interval = 10e-9 * scale;
}

void check_cell_fits(double cell_size, double diameter, const std::string& where,
                     const std::string& key) {
  if (cell_size > 0.0 && diameter < 2.0 * cell_size)
    throw InputError(where, key,
                     fmt::format("the cell ({:.4g} um) must be at most half the particle "
                                 "diameter ({:.4g} um)",
                                 cell_size * 1e6, diameter * 1e6));
}

namespace {

// The generated case's header: the command that made it and what it models.
void append_header(std::string& y, const ImpactSpec& spec, const std::string& substrate_material,
                   const SubstrateSize& substrate, bool quarter) {
  auto comment = [&y](std::string_view text) { append_comment(y, text); };
  y += "# Generated by: " + one_line(spec.command) + "\n";  // one line, to copy and paste
  comment(fmt::format(
      "A {} um particle of {} hits a substrate of {} at {} m/s, starting at first contact "
      "(thesis §5.2.1): its bottom touches the substrate's top face z = 0 at t = 0. The "
      "substrate cylinder is {} across and {} high, {}.",
      short_number(spec.diameter / kUm), spec.material, substrate_material,
      short_number(spec.speed), um(substrate.diameter), um(substrate.height),
      spec.setup == SetUp::Similar
          ? fmt::format("{} and {} particle diameters, and the grid, times and outputs are in "
                        "proportion to the diameter too (the size-similar set-up, "
                        "docs/impact.md)",
                        number(kSimilarSubstrateDiameter), number(kSimilarSubstrateHeight))
          : std::string("after thesis Table 5.3 (the thesis' set-up, docs/impact.md)")));
  if (quarter)
    comment(
        "One quarter is modelled: the planes x = 0 and y = 0 are symmetry planes (roller faces "
        "of the grid), where the solver cuts the bodies.");
}

// The MPM impact's grid (a quarter's box and roller faces on its symmetry planes), its solver
// settings and the thesis' contact normal.
void append_grid_and_solver(std::string& y, const ImpactSpec& spec, const SubstrateSize& substrate,
                            bool quarter) {
  auto line = [&y](const std::string& text) { y += text + "\n"; };
  line("grid:");
  line("  cell_size: " + um(spec.cell_size));
  if (quarter) {
    const QuarterGrid q = quarter_grid(spec.diameter, substrate, spec.cell_size);
    line("  min: " + vector_um(q.min));
    line("  max: " + vector_um(q.max));
    line("  faces: {xmin: roller, ymin: roller}   # the symmetry planes");
  }
  line("solver:");
  line(std::string("  geometry: ") +
       (spec.geometry == case_file::Geometry::Axisymmetric ? "axisymmetric" : "3d"));
  line("  shape_function: " + spec.shape_function);
  line(fmt::format("  end_time: {} ns", number(spec.end_time * 1e9)));
  line("contact:");
  line("  mpm:");
  line("    normal: body:substrate   # the thesis' choice in all its tests (§3.5.4)");
}

// Which option set each generated key of the MPM impact, for errors located at the option.
std::vector<case_file::ValueOrigin> mpm_origins(const ImpactSpec& spec) {
  std::vector<case_file::ValueOrigin> origins = {
      {"bodies.particle.material", "--material"},
      {"bodies.substrate.material",
       spec.substrate_material.empty() ? "--material" : "--substrate-material"},
      {"bodies.particle.shape", "--diameter"},
      {"bodies.substrate.shape", "--diameter"},
      {"bodies.particle.velocity", "--velocity"},
      {"bodies.particle.spacing", "--grid"},
      {"bodies.substrate.spacing", "--grid"},
      {"grid.cell_size", "--grid"},
      {"solver.geometry", "--geometry"},
      {"solver.shape_function", "--shape-function"},
      {"solver.end_time", "--end-time"},
      {"bonding.model", "--bonding"}};
  if (spec.coarsening > 0) origins.push_back({"bodies.substrate.coarsening", "--coarsening"});
  return origins;
}

// The bonding section: the model and the parameters the options gave.
void append_bonding(std::string& y, const ImpactSpec& spec,
                    std::vector<case_file::ValueOrigin>& origins) {
  auto line = [&y](const std::string& text) { y += text + "\n"; };
  line("bonding:");
  line("  model: " + spec.bonding);
  // Parameters not given keep the schema's defaults (the thesis' calibration, §5.1.4), so a
  // new calibration in the schema reaches generated cases too.
  auto parameter = [&line, &origins](const char* key, const char* option, const std::string& text) {
    line(fmt::format("  {}: {}", key, text));
    origins.push_back({fmt::format("bonding.{}", key), option});
  };
  if (spec.critical_energy)
    parameter("critical_energy", "--Gc", number(*spec.critical_energy) + " J/m^2");
  if (spec.critical_energy_rate)
    parameter("critical_energy_rate", "--Gc-rate",
              number(*spec.critical_energy_rate * 1e-6) + " J/m^2/us");
  if (spec.critical_strain) parameter("critical_strain", "--eps-c", number(*spec.critical_strain));
  if (spec.critical_strain_rate)
    parameter("critical_strain_rate", "--eps-c-rate", number(*spec.critical_strain_rate) + " 1/s");
  if (spec.floor) parameter("floor", "--floor", number(*spec.floor));
}

}  // namespace

GeneratedCase impact_case(const ImpactSpec& spec) {
  if (spec.solver == case_file::Method::Peridynamics) return peridynamics_impact_case(spec);
  const std::string substrate_material =
      spec.substrate_material.empty() ? spec.material : spec.substrate_material;
  const bool axisymmetric = spec.geometry == case_file::Geometry::Axisymmetric;
  const bool quarter = !axisymmetric && spec.symmetry == Symmetry::Quarter;
  const SubstrateSize substrate = substrate_size(spec.diameter, spec.setup);
  const std::string geometry_text =
      axisymmetric ? "axisymmetric" : (quarter ? "3d (one quarter)" : "3d (whole)");

  GeneratedCase g;
  g.name = folder_safe(
      fmt::format("impact-{}{}-{}um-{}{}", spec.material,
                  substrate_material == spec.material ? "" : "-on-" + substrate_material,
                  short_number(spec.diameter / kUm), short_number(spec.speed),
                  axisymmetric ? "" : (quarter ? "-3d" : "-3d-whole")));

  std::string y;
  auto line = [&y](const std::string& text) { y += text + "\n"; };
  append_header(y, spec, substrate_material, substrate, quarter);
  line("name: " + g.name);
  line("description: " +
       yaml_scalar(fmt::format("{} {} um sphere at {} m/s on a {} x {} {} cylinder, {}",
                               spec.material, short_number(spec.diameter / kUm),
                               short_number(spec.speed), um(substrate.diameter),
                               um(substrate.height), substrate_material, geometry_text)));
  append_bodies(y, spec, substrate_material, 0.5 * substrate.diameter, substrate.height);
  line("    absorbing: [bottom, side]   # a semi-infinite substrate (thesis §3.5.5)");
  if (spec.coarsening > 0) append_coarsening(y, spec, substrate);
  append_grid_and_solver(y, spec, substrate, quarter);
  g.origins = mpm_origins(spec);
  append_bonding(y, spec, g.origins);
  if (spec.verdict_window > 0.0) {
    line("metrics:");
    line(fmt::format("  verdict_window: {} ns", number(spec.verdict_window * 1e9)));
  }
  line("output:");
  line(fmt::format("  history_interval: {} ns", number(spec.history_interval * 1e9)));
  line(fmt::format("  snapshot_interval: {} ns", number(spec.snapshot_interval * 1e9)));
  g.yaml = std::move(y);
  return g;
}

}  // namespace coldspray::setups
