// The case-file schema: each struct's YAML keys, units, presence and ranges, written once.
// The Reader (parsing), the Writer (the resolved echo) and the key lists all run these same
// functions, so the echo cannot drift from the parser. docs/input-reference.md documents them.
//
// An IO provides: scalar, scalars, table, quantity, vector, section, section_either, variant,
// list, materials and check (see reader.hpp for their meaning).
#pragma once

#include <array>
#include <string_view>

#include "case/case.hpp"
#include "case/codecs.hpp"
#include "case/field_rules.hpp"
#include "case/material_schema.hpp"
#include "core/units.hpp"

namespace coldspray::case_file {

inline constexpr std::array<std::string_view, 3> kShapeTypes{"sphere", "cylinder", "box"};

inline constexpr Names<BodyFace, 3> kBodyFaceNames{
    {{{"bottom", BodyFace::Bottom}, {"side", BodyFace::Side}, {"top", BodyFace::Top}}}};

inline constexpr Names<GridFace, 6> kGridFaceNames{{{{"xmin", GridFace::XMin},
                                                     {"xmax", GridFace::XMax},
                                                     {"ymin", GridFace::YMin},
                                                     {"ymax", GridFace::YMax},
                                                     {"zmin", GridFace::ZMin},
                                                     {"zmax", GridFace::ZMax}}}};

inline constexpr Names<FaceCondition, 3> kFaceConditionNames{{{{"free", FaceCondition::Free},
                                                               {"fixed", FaceCondition::Fixed},
                                                               {"roller", FaceCondition::Roller}}}};

inline constexpr Names<Method, 2> kMethodNames{
    {{{"mpm", Method::Mpm}, {"peridynamics", Method::Peridynamics}}}};

inline constexpr Names<Influence, 2> kInfluenceNames{
    {{{"constant", Influence::Constant}, {"inverse_distance", Influence::InverseDistance}}}};
inline constexpr Names<ControlStiffness, 2> kControlStiffnessNames{
    {{{"elastic", ControlStiffness::Elastic}, {"flow", ControlStiffness::Flow}}}};

inline constexpr Names<Geometry, 2> kGeometryNames{
    {{{"3d", Geometry::ThreeD}, {"axisymmetric", Geometry::Axisymmetric}}}};

inline constexpr Names<ShapeFunction, 2> kShapeFunctionNames{
    {{{"linear", ShapeFunction::Linear}, {"gimp", ShapeFunction::Gimp}}}};

inline constexpr Names<BondingModel, 3> kBondingModelNames{{{{"none", BondingModel::None},
                                                             {"strain", BondingModel::Strain},
                                                             {"energy", BondingModel::Energy}}}};

inline constexpr Names<DebondLaw, 2> kDebondLawNames{
    {{{"none", DebondLaw::None}, {"cohesive", DebondLaw::Cohesive}}}};

inline constexpr Names<ContactNormal, 3> kOtherPairsNormalNames{
    {{{"max-gradient", ContactNormal::MaxGradient},
      {"average-gradient", ContactNormal::AverageGradient},
      {"highest-id", ContactNormal::HighestId}}}};

inline constexpr Names<ContactModel, 3> kContactModelNames{
    {{{"repulsive", ContactModel::Repulsive},
      {"lennard-jones", ContactModel::LennardJones},
      {"interface-bonds", ContactModel::InterfaceBonds}}}};

inline constexpr Names<NodalAverage, 2> kNodalAverageNames{
    {{{"count", NodalAverage::Count}, {"weight", NodalAverage::Weight}}}};

inline constexpr std::array<std::string_view, 14> kProbeFields{
    "pressure", "von_mises", "density",  "temperature", "eqps",       "sigma_xx",   "sigma_yy",
    "sigma_zz", "sigma_xy",  "sigma_yz", "sigma_xz",    "velocity_x", "velocity_y", "velocity_z"};

// contact.mpm.normal: "max-gradient", "average-gradient", "highest-id" or "body:NAME"; sets normal
// and normal_body.
struct ContactNormalText {
  std::string expected() const { return "max-gradient, average-gradient, highest-id or body:NAME"; }
  void parse(std::string_view text, MpmContact& contact) const;
  std::string format(const MpmContact& contact) const;
};

// A case name names the default output folder.
bool is_folder_name(const std::string& name);

template <class IO>
void fields(IO& io, geometry::Sphere& s) {
  io.vector("center", s.center, units::kLength, kRequired);
  io.quantity("radius", s.radius, units::kLength, kRequired, kPositive);
}

template <class IO>
void fields(IO& io, geometry::Cylinder& c) {
  io.vector("base_center", c.base_center, units::kLength, kRequired);
  io.quantity("radius", c.radius, units::kLength, kRequired, kPositive);
  io.quantity("height", c.height, units::kLength, kRequired, kPositive);
}

template <class IO>
void fields(IO& io, geometry::Box& b) {
  io.vector("min", b.min, units::kLength, kRequired);
  io.vector("max", b.max, units::kLength, kRequired);
  io.check((b.min.array() < b.max.array()).all(), "max",
           "must be greater than min in every component");
}

template <class IO>
void fields(IO& io, Coarsening& c) {
  io.scalar("levels", c.levels, WholeNumber{1}, kOptional);
  io.variant("fine", c.fine, "type", kShapeTypes, kRequired);
}

template <class IO>
void fields(IO& io, Body& b) {
  io.scalar("name", b.name, Text{}, kRequired);
  io.scalar("material", b.material, Text{}, kRequired);
  io.variant("shape", b.shape, "type", kShapeTypes, kRequired);
  io.quantity("spacing", b.spacing, units::kLength, kRequired, kPositive);
  io.vector("velocity", b.velocity, units::kVelocity, kOptional);
  io.quantity("temperature", b.temperature, units::kTemperature, kOptional, kPositive);
  io.scalars("absorbing", b.absorbing, kBodyFaceNames, kOptional);
  io.scalars("fixed", b.fixed, kBodyFaceNames, kOptional);
  io.scalars("roller", b.roller, kBodyFaceNames, kOptional);
  io.section("coarsening", b.coarsening, kOptional);
}

template <class IO>
void fields(IO& io, Grid& g) {
  io.quantity("cell_size", g.cell_size, units::kLength, kRequired, kPositive);
  io.vector("min", g.min, units::kLength, kOptional);
  io.vector("max", g.max, units::kLength, kOptional);
  io.check(g.min.has_value() == g.max.has_value(), g.min ? "min" : "max",
           "give both grid.min and grid.max, or neither");
  // y is checked with the geometry (case/validate.cpp): r-z runs do not use it.
  io.check(!g.min || !g.max || ((*g.min)[0] < (*g.max)[0] && (*g.min)[2] < (*g.max)[2]), "max",
           "must be greater than min in x and z");
  io.table("faces", g.faces, kGridFaceNames, kFaceConditionNames, FaceCondition::Free);
}

template <class IO>
void fields(IO& io, ArtificialViscosity& a) {
  io.scalar("enabled", a.enabled, Flag{}, kOptional);
  io.quantity("linear", a.linear, units::kDimensionless, kOptional, kNonNegative);
  io.quantity("quadratic", a.quadratic, units::kDimensionless, kOptional, kNonNegative);
}

template <class IO>
void fields(IO& io, Solver& s) {
  io.scalar("method", s.method, kMethodNames, kOptional);
  io.scalar("geometry", s.geometry, kGeometryNames, kOptional);
  io.scalar("shape_function", s.shape_function, kShapeFunctionNames, kOptional);
  io.quantity("end_time", s.end_time, units::kTime, kRequired, kPositive);
  io.quantity("cfl", s.cfl, units::kDimensionless, kOptional, Range{0.0, kMaxCfl, true, false});
  io.quantity("dt_scale", s.dt_scale, units::kDimensionless, kOptional, kFraction);
  io.section("artificial_viscosity", s.artificial_viscosity, kOptional);
  io.scalar("heat_conduction", s.heat_conduction, Flag{}, kOptional);
}

template <class IO>
void fields(IO& io, MpmContact& c) {
  io.scalar("normal", c, ContactNormalText{}, kOptional);
  io.scalar("other_pairs_normal", c.other_pairs_normal, kOtherPairsNormalNames, kOptional);
  io.quantity("friction", c.friction, units::kDimensionless, kOptional, kNonNegative);
  io.scalar("gap_check", c.gap_check, Flag{}, kOptional);
}

template <class IO>
void fields(IO& io, Repulsion& r) {
  io.quantity("distance", r.distance, units::kDimensionless, kOptional,
              Range{0.0, 3.0, true, false});
  io.quantity("initial_fraction", r.initial_fraction, units::kDimensionless, kOptional, kFraction);
  io.quantity("stiffness", r.stiffness, units::kDimensionless, kOptional, kNonNegative);
}

template <class IO>
void fields(IO& io, PeridynamicsContact& c) {
  io.scalar("model", c.model, kContactModelNames, kOptional);
  io.section("repulsion", c.repulsion, kOptional);
  io.quantity("beta", c.beta, units::kDimensionless, kOptional, Range{0.0, 1.0, true, true});
  io.quantity("r0", c.r0, units::kDimensionless, kOptional, kPositive);
  io.quantity("cutoff", c.cutoff, units::kDimensionless, kOptional,
              Range{1.0, kInfinity, true, false});
  io.quantity("alpha", c.alpha, units::kEnergy, kOptional, kPositive);
  io.quantity("repulsion_exponent", c.repulsion_exponent, units::kDimensionless, kOptional,
              kPositive);
  io.quantity("attraction_exponent", c.attraction_exponent, units::kDimensionless, kOptional,
              kPositive);
  io.check(c.repulsion_exponent > c.attraction_exponent, "repulsion_exponent",
           "must exceed attraction_exponent (the repulsion must win at short range)");
  io.quantity("fracture_energy", c.fracture_energy, units::kEnergyPerArea, kOptional, kPositive);
  io.quantity("yield_stretch", c.yield_stretch, units::kDimensionless, kOptional,
              Range{0.0, 1.0, true, true});
  io.quantity("softening", c.softening, units::kDimensionless, kOptional, kPositive);
}

template <class IO>
void fields(IO& io, Contact& c) {
  io.section("mpm", c.mpm, kOptional);
  io.section("peridynamics", c.peridynamics, kOptional);
}

template <class IO>
void fields(IO& io, Debond& d) {
  io.scalar("law", d.law, kDebondLawNames, kOptional);
  io.quantity("strength", d.strength, units::kPressure, kOptional, kPositive);
  io.quantity("fracture_energy", d.fracture_energy, units::kEnergyPerArea, kOptional, kPositive);
  io.quantity("shear_ratio", d.shear_ratio, units::kDimensionless, kOptional, kPositive);
}

template <class IO>
void fields(IO& io, Bonding& b) {
  io.scalar("model", b.model, kBondingModelNames, kOptional);
  io.quantity("critical_strain", b.critical_strain, units::kDimensionless, kOptional, kPositive);
  io.quantity("critical_strain_rate", b.critical_strain_rate, units::kRate, kOptional, kPositive);
  io.quantity("critical_energy", b.critical_energy, units::kEnergyPerArea, kOptional, kPositive);
  io.quantity("critical_energy_rate", b.critical_energy_rate, units::kEnergyPerAreaPerTime,
              kOptional, kPositive);
  io.quantity("floor", b.floor, units::kDimensionless, kOptional, kFraction);
  io.quantity("critical_penetration", b.critical_penetration, units::kDimensionless, kOptional,
              Range{0.0, 1.0, false, true});
  io.scalar("nodal_average", b.nodal_average, kNodalAverageNames, kOptional);
  io.section("debond", b.debond, kOptional);
}

template <class IO>
void fields(IO& io, ImpactMetrics& m) {
  io.quantity("rest_speed_limit", m.rest_speed_limit, units::kVelocity, kOptional, kPositive);
  io.quantity("bonded_separation_speed", m.bonded_separation_speed, units::kVelocity, kOptional,
              kPositive);
  io.quantity("verdict_window", m.verdict_window, units::kTime, kOptional, kPositive);
  io.scalar("verdict_extensions", m.verdict_extensions, WholeNumber{0}, kOptional);
}

template <class IO>
void fields(IO& io, Peridynamics& p) {
  io.quantity("horizon_factor", p.horizon_factor, units::kDimensionless, kOptional,
              Range{2.0, 6.0, false, false});
  io.scalar("influence", p.influence, kInfluenceNames, kOptional);
  io.quantity("stabilization", p.stabilization, units::kDimensionless, kOptional, kNonNegative);
  io.scalar("control_stiffness", p.control_stiffness, kControlStiffnessNames, kOptional);
  io.scalar("subcycling", p.subcycling, Flag{}, kOptional);
}

template <class IO>
void fields(IO& io, Grip& g) {
  io.scalar("body", g.body, Text{}, kRequired);
  io.quantity("fraction", g.fraction, units::kDimensionless, kOptional, kFraction);
  io.vector("velocity", g.velocity, units::kVelocity, kRequired);
  io.check(g.velocity.norm() > 0.0, "velocity", "must not be zero: the grip pulls at it");
  io.vector("side", g.side, units::kDimensionless, kOptional);
  io.quantity("ramp", g.ramp, units::kTime, kOptional, kNonNegative);
}

template <class IO>
void fields(IO& io, Symmetry& s) {
  io.quantity("x", s.x, units::kLength, kOptional);
  io.quantity("y", s.y, units::kLength, kOptional);
}

template <class IO>
void fields(IO& io, Probe& p) {
  io.scalar("name", p.name, Text{}, kRequired);
  io.vector("position", p.position, units::kLength, kRequired);
  io.scalars("fields", p.fields, Keywords{kProbeFields}, kRequired);
  io.check(!p.fields.empty(), "fields", "needs at least one field");
}

template <class IO>
void fields(IO& io, Output& o) {
  io.quantity("history_interval", o.history_interval, units::kTime, kOptional, kNonNegative);
  io.quantity("snapshot_interval", o.snapshot_interval, units::kTime, kOptional, kNonNegative);
  io.list("probes", o.probes, kOptional);
  io.quantity("checkpoint_interval", o.checkpoint_interval, units::kTime, kOptional, kNonNegative);
  io.quantity("checkpoint_wall_interval", o.checkpoint_wall_interval, units::kTime, kOptional,
              kNonNegative);
  io.scalar("checkpoint_keep", o.checkpoint_keep, WholeNumber{1}, kOptional);
}

// Up to 1e15: the seeding's lattice indices and the grid's node counts stay far inside their
// integer types below it.
inline constexpr Range kCountLimit{1.0, 1e15, false, false};

template <class IO>
void fields(IO& io, Limits& l) {
  io.quantity("max_points", l.max_points, units::kDimensionless, kOptional, kCountLimit);
  io.quantity("max_grid_nodes", l.max_grid_nodes, units::kDimensionless, kOptional, kCountLimit);
  io.quantity("max_steps", l.max_steps, units::kDimensionless, kOptional, kCountLimit);
}

template <class IO>
void fields(IO& io, Case& c) {
  io.scalar("name", c.name, Text{}, kRequired);
  io.check(is_folder_name(c.name), "name",
           "must be usable as a folder name (not empty, no '/', not '.' or '..')");
  io.scalar("description", c.description, Text{}, kOptional);
  io.materials("materials", c.materials);
  io.list("bodies", c.bodies, kRequired);
  io.check(!c.bodies.empty(), "bodies", "needs at least one body");
  // Required by the MPM: case/validate.cpp, which knows the solver.
  io.section("grid", c.grid, kOptional);
  io.section("solver", c.solver, kRequired);
  io.section("peridynamics", c.peridynamics, kOptional);
  io.section("symmetry", c.symmetry, kOptional);
  io.section("grip", c.grip, kOptional);
  io.section("contact", c.contact, kOptional);
  io.section("bonding", c.bonding, kOptional);
  io.section("metrics", c.metrics, kOptional);
  io.section("output", c.output, kOptional);
  io.section("limits", c.limits, kOptional);
}

}  // namespace coldspray::case_file
