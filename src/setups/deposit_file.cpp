#include "setups/deposit_file.hpp"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <string_view>
#include <variant>

#include "case/case_schema.hpp"
#include "case/codecs.hpp"
#include "case/document.hpp"
#include "case/reader.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "setups/impact_case.hpp"
#include "setups/map_file.hpp"

namespace coldspray::setups {

namespace {

using case_file::kOptional;
using case_file::kRequired;

constexpr std::array<std::string_view, 3> kDistributions{"fixed", "normal", "log-normal"};
constexpr std::array<std::string_view, 3> kBondingModels{"none", "strain", "energy"};
// `substrate`: the substrate's normal at particle-substrate pairs (the rule the bonding model is
// calibrated with), the average gradient between particles (case keys contact.mpm.normal and
// contact.mpm.other_pairs_normal); the others are contact.mpm.normal's own.
constexpr std::array<std::string_view, 4> kContactNormals{"substrate", "highest-id",
                                                          "average-gradient", "max-gradient"};
constexpr case_file::Range kAtLeastOne{1.0, case_file::kInfinity, false, false};

struct FixedSizes {
  double size = 0.0;
};
template <class IO>
void fields(IO& io, FixedSizes& d) {
  io.quantity("size", d.size, units::kLength, kRequired, case_file::kPositive);
}

struct NormalSizes {
  double mean = 0.0, deviation = 0.0;
};
template <class IO>
void fields(IO& io, NormalSizes& d) {
  io.quantity("mean", d.mean, units::kLength, kRequired, case_file::kPositive);
  io.quantity("deviation", d.deviation, units::kLength, kRequired, case_file::kNonNegative);
  io.check(d.mean > studies::kSizeDeviations * d.deviation, "deviation",
           fmt::format("reaches sizes <= 0 within {:g} deviations of the mean (the draws' range): "
                       "the mean must exceed {:g} deviations",
                       studies::kSizeDeviations, studies::kSizeDeviations));
}

struct LogNormalSizes {
  double median = 0.0, spread = 1.0;
};
template <class IO>
void fields(IO& io, LogNormalSizes& d) {
  io.quantity("median", d.median, units::kLength, kRequired, case_file::kPositive);
  io.quantity("spread", d.spread, units::kDimensionless, kRequired, kAtLeastOne);
}

using Sizes = std::variant<FixedSizes, NormalSizes, LogNormalSizes>;

struct ParticlesEntry {
  int count = 0;
  std::string material;
  Sizes diameter;
  double velocity = 0.0;
  double velocity_exponent = 0.0;
  std::optional<double> velocity_diameter;
  double temperature = 298.0;
};
template <class IO>
void fields(IO& io, ParticlesEntry& p) {
  io.scalar("count", p.count, case_file::WholeNumber{1}, kRequired);
  io.scalar("material", p.material, case_file::Text{}, kRequired);
  io.variant("diameter", p.diameter, "distribution", kDistributions, kRequired);
  io.quantity("velocity", p.velocity, units::kVelocity, kRequired, case_file::kPositive);
  io.quantity("velocity_exponent", p.velocity_exponent, units::kDimensionless, kOptional);
  io.quantity("velocity_diameter", p.velocity_diameter, units::kLength, kOptional,
              case_file::kPositive);
  io.quantity("temperature", p.temperature, units::kTemperature, kOptional, case_file::kPositive);
}

struct SubstrateEntry {
  std::string material;
  // Unset: the size-similar set-up's, kSimilarSubstrateHeight typical diameters.
  std::optional<double> thickness;
  std::optional<double> margin;
  double temperature = 298.0;
  int coarsening = 0;
};
template <class IO>
void fields(IO& io, SubstrateEntry& s) {
  io.scalar("material", s.material, case_file::Text{}, kOptional);
  io.quantity("thickness", s.thickness, units::kLength, kOptional, case_file::kPositive);
  io.quantity("margin", s.margin, units::kLength, kOptional, case_file::kNonNegative);
  io.quantity("temperature", s.temperature, units::kTemperature, kOptional, case_file::kPositive);
  io.scalar("coarsening", s.coarsening, case_file::WholeNumber{0}, kOptional);
}

struct PatchEntry {
  double x = 0.0, y = 0.0;
};
template <class IO>
void fields(IO& io, PatchEntry& p) {
  io.quantity("x", p.x, units::kLength, kRequired, case_file::kNonNegative);
  io.quantity("y", p.y, units::kLength, kRequired, case_file::kNonNegative);
}

struct FileEntry {
  std::string name, description, grid;
  int seed = 1;
  ParticlesEntry particles;
  SubstrateEntry substrate;
  PatchEntry patch;
  double arrival_window = 0.0;
  // Unset: a verdict window after the typical particle has left the contact
  // (setups/impact_case.hpp).
  std::optional<double> settle_time;
  std::optional<double> voxel;
  std::string bonding = "energy", contact_normal = "substrate";
};
template <class IO>
void fields(IO& io, FileEntry& f) {
  io.scalar("name", f.name, case_file::Text{}, kRequired);
  io.check(case_file::is_folder_name(f.name), "name",
           "names the output folder: use letters, digits, '.', '-' and '_'");
  io.scalar("description", f.description, case_file::Text{}, kOptional);
  io.scalar("seed", f.seed, case_file::WholeNumber{0}, kOptional);
  io.section("particles", f.particles, kRequired);
  io.section("substrate", f.substrate, kOptional);
  io.section("patch", f.patch, kRequired);
  io.quantity("arrival_window", f.arrival_window, units::kTime, kRequired, case_file::kNonNegative);
  io.quantity("settle_time", f.settle_time, units::kTime, kOptional, case_file::kPositive);
  io.scalar("grid", f.grid, case_file::Text{}, kRequired);
  io.quantity("voxel", f.voxel, units::kLength, kOptional, case_file::kPositive);
  io.scalar("bonding", f.bonding, case_file::Keywords{kBondingModels}, kOptional);
  io.scalar("contact_normal", f.contact_normal, case_file::Keywords{kContactNormals}, kOptional);
}

studies::SizeDistribution size_distribution(const Sizes& sizes) {
  using Kind = studies::SizeDistribution::Kind;
  if (const auto* f = std::get_if<FixedSizes>(&sizes)) return {Kind::Fixed, f->size, 0.0};
  if (const auto* n = std::get_if<NormalSizes>(&sizes))
    return {Kind::Normal, n->mean, n->deviation};
  const auto& l = std::get<LogNormalSizes>(sizes);
  return {Kind::LogNormal, l.median, l.spread};
}

std::string where_of(const case_file::Document& doc, std::initializer_list<std::string> path) {
  const std::vector<std::string> keys(path);
  return doc.where(keys);
}

}  // namespace

DepositFile read_deposit_file(const std::string& path) {
  const case_file::Document doc = read_map_file(path);
  const YAML::Node& root = doc.root();
  FileEntry f;
  case_file::Reader::read(doc, root, "", f);

  DepositFile d;
  d.path = d.file_where = path;
  d.particles_where = where_of(doc, {"particles"});
  d.count_where = where_of(doc, {"particles", "count"});
  d.patch_where = where_of(doc, {"patch"});
  d.grid_where = where_of(doc, {"grid"});
  d.substrate_where = root["substrate"] ? where_of(doc, {"substrate"}) : path;
  d.name = f.name;
  d.description = f.description;
  d.material = f.particles.material;
  d.substrate_material = f.substrate.material.empty() ? d.material : f.substrate.material;
  d.temperature = f.particles.temperature;
  d.substrate_temperature = f.substrate.temperature;
  d.coarsening = f.substrate.coarsening;
  d.bonding = f.bonding;
  d.contact_normal = f.contact_normal;

  studies::DepositPlan& plan = d.plan;
  plan.count = f.particles.count;
  plan.diameter = size_distribution(f.particles.diameter);
  // The size-similar set-up (docs/impact.md) for the distribution's typical particle: the grid
  // as cells across it, the substrate and the times in proportion to it.
  const double typical = plan.diameter.centre;
  try {
    const GridChoice grid = parse_grid_choice(f.grid);
    d.cell_size = grid.cell(typical);
    d.spacing = grid.point_spacing(typical);
  } catch (const UnitError& e) {
    throw InputError(d.grid_where, "grid", e.what());
  }
  d.substrate_thickness = f.substrate.thickness.value_or(kSimilarSubstrateHeight * typical);
  d.verdict_window = 20e-9 * typical / kThesisTimesDiameter;
  d.settle_time =
      f.settle_time.value_or(d.verdict_window + kContactTimes * typical / f.particles.velocity);
  plan.speed = f.particles.velocity;
  plan.speed_exponent = f.particles.velocity_exponent;
  plan.speed_diameter = f.particles.velocity_diameter.value_or(plan.diameter.centre);
  plan.patch = {f.patch.x, f.patch.y};
  plan.arrival_window = f.arrival_window;
  plan.seed = static_cast<std::uint64_t>(f.seed);
  // No grid node is reached by two particles at t = 0: a GIMP point's support reaches a cell
  // and half its own width beyond it (mpm/shape_functions.hpp), so two points more than two
  // cells and a spacing apart share no node.
  plan.clearance = 2.0 * d.cell_size + d.spacing;
  d.voxel = f.voxel.value_or(d.spacing);
  d.substrate_margin = f.substrate.margin.value_or(plan.diameter.largest());
  check_cell_fits(d.cell_size, plan.diameter.smallest(), d.particles_where,
                  "particles.diameter (its smallest draw)");
  return d;
}

}  // namespace coldspray::setups
