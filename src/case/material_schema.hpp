// The material schema (the syntax of data/materials/*.yaml and of a case's `materials:`),
// written once for the Reader, the Writer, the key lists and print_material.
#pragma once

#include <array>
#include <string_view>
#include <type_traits>

#include "case/codecs.hpp"
#include "case/field_rules.hpp"
#include "core/units.hpp"
#include "core/variant_names.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file {

// The top-level groups of a material; `sources:` gives the provenance of each.
inline constexpr std::array<std::string_view, 10> kMaterialGroups{
    "density", "elastic",       "strength",       "shear_modulus_model",  "melt",
    "eos",     "specific_heat", "taylor_quinney", "thermal_conductivity", "surface_energy"};

// Each model's `model:` names, the kName of the variant's alternatives in its order: io.variant
// matches a name to the alternative at its position.
inline constexpr auto kStrengthModels = variant_names<materials::strength::Model>();
inline constexpr auto kShearModulusModels = variant_names<materials::shear_modulus::Model>();
inline constexpr auto kMeltModels = variant_names<materials::melt::Model>();
inline constexpr auto kEosModels = variant_names<materials::eos::Model>();

// The other way to give `elastic:`, converted to shear and bulk moduli when read.
struct YoungsPoisson {
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // nu
  // G = E / (2 (1 + nu)), K = E / (3 (1 - 2 nu)).
  materials::Elastic converted() const {
    return {youngs_modulus / (2.0 * (1.0 + poisson_ratio)),
            youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio))};
  }
};

// Tags a section that may be written in an alternative form.
template <class Alternative>
inline constexpr std::type_identity<Alternative> kAlternativeForm{};

template <class IO>
void fields(IO& io, materials::Elastic& e) {
  io.quantity("shear_modulus", e.shear_modulus, units::kPressure, kRequired, kPositive);
  io.quantity("bulk_modulus", e.bulk_modulus, units::kPressure, kRequired, kPositive);
}

template <class IO>
void fields(IO& io, YoungsPoisson& e) {
  io.quantity("youngs_modulus", e.youngs_modulus, units::kPressure, kRequired, kPositive);
  io.quantity("poisson_ratio", e.poisson_ratio, units::kDimensionless, kRequired, kPoissonRatio);
}

template <class IO>
void fields(IO&, materials::strength::Elastic&) {}

template <class IO>
void fields(IO& io, materials::strength::VonMises& s) {
  io.quantity("yield_stress", s.yield_stress, units::kPressure, kRequired, kPositive);
  io.quantity("hardening_modulus", s.hardening_modulus, units::kPressure, kOptional, kNonNegative);
}

template <class IO>
void fields(IO& io, materials::strength::JohnsonCook& s) {
  using units::kDimensionless;
  io.quantity("A", s.A, units::kPressure, kRequired, kPositive);
  io.quantity("B", s.B, units::kPressure, kRequired, kNonNegative);
  io.quantity("n", s.n, kDimensionless, kRequired, kNonNegative);
  io.quantity("C", s.C, kDimensionless, kRequired, kNonNegative);
  io.quantity("m", s.m, kDimensionless, kRequired, kPositive);
  io.quantity("reference_strain_rate", s.reference_strain_rate, units::kRate, kOptional, kPositive);
  io.quantity("reference_temperature", s.reference_temperature, units::kTemperature, kOptional,
              kPositive);
}

template <class IO>
void fields(IO& io, materials::strength::Ptw& s) {
  using units::kDimensionless;
  io.quantity("theta", s.theta, kDimensionless, kRequired, kNonNegative);
  io.quantity("p", s.p, kDimensionless, kRequired, kPositive);
  io.quantity("s0", s.s0, kDimensionless, kRequired, kPositive);
  io.quantity("s_inf", s.s_inf, kDimensionless, kRequired, kNonNegative);
  io.quantity("kappa", s.kappa, kDimensionless, kRequired, kPositive);
  io.quantity("gamma", s.gamma, kDimensionless, kRequired, kPositive);
  io.quantity("y0", s.y0, kDimensionless, kRequired, kNonNegative);
  io.quantity("y_inf", s.y_inf, kDimensionless, kRequired, kNonNegative);
  io.quantity("y1", s.y1, kDimensionless, kRequired, kNonNegative);
  io.quantity("y2", s.y2, kDimensionless, kRequired, kNonNegative);
  io.quantity("s1", s.s1, kDimensionless, kRequired, kNonNegative);
  io.quantity("atomic_mass", s.atomic_mass, units::kMass, kRequired, kPositive);
  // PTW's saturation stresses bound its yield stresses (Preston et al. 2003, eq 13).
  io.check(s.y0 <= s.s0, "y0", "PTW needs y0 <= s0");
  io.check(s.y_inf <= s.s_inf, "y_inf", "PTW needs y_inf <= s_inf");
}

template <class IO>
void fields(IO&, materials::shear_modulus::Constant&) {}

template <class IO>
void fields(IO& io, materials::shear_modulus::Mts& g) {
  io.quantity("mu0", g.mu0, units::kPressure, kRequired, kPositive);
  io.quantity("D", g.D, units::kPressure, kRequired, kNonNegative);
  io.quantity("T0", g.T0, units::kTemperature, kRequired, kPositive);
}

template <class IO>
void fields(IO& io, materials::melt::Constant& t) {
  io.quantity("temperature", t.temperature, units::kTemperature, kRequired, kPositive);
}

template <class IO>
void fields(IO& io, materials::melt::Scg& t) {
  io.quantity("Tm0", t.Tm0, units::kTemperature, kRequired, kPositive);
  io.quantity("a", t.a, units::kDimensionless, kRequired, kNonNegative);
  io.quantity("gamma0", t.gamma0, units::kDimensionless, kRequired, kNonNegative);
}

template <class IO>
void fields(IO&, materials::eos::Linear&) {}

template <class IO>
void fields(IO& io, materials::eos::MieGruneisen& e) {
  io.quantity("c0", e.c0, units::kVelocity, kRequired, kPositive);
  io.quantity("s", e.s, units::kDimensionless, kRequired, kNonNegative);
  io.quantity("gamma0", e.gamma0, units::kDimensionless, kRequired, kNonNegative);
}

template <class IO>
void fields(IO& io, materials::Material& m) {
  io.scalar("description", m.description, Text{}, kOptional);
  io.quantity("density", m.density, units::kDensity, kRequired, kPositive);
  io.section_either("elastic", m.elastic, kRequired, kAlternativeForm<YoungsPoisson>);
  io.variant("strength", m.strength, "model", kStrengthModels, kRequired);
  io.variant("shear_modulus_model", m.shear_modulus, "model", kShearModulusModels, kOptional);
  io.variant("melt", m.melt, "model", kMeltModels, kRequired);
  io.variant("eos", m.eos, "model", kEosModels, kOptional);
  io.quantity("specific_heat", m.thermal.specific_heat, units::kSpecificHeat, kRequired, kPositive);
  io.quantity("taylor_quinney", m.thermal.taylor_quinney, units::kDimensionless, kOptional,
              kUnitInterval);
  io.quantity("thermal_conductivity", m.thermal.conductivity, units::kThermalConductivity,
              kOptional, kNonNegative);
  io.quantity("surface_energy", m.surface_energy, units::kEnergyPerArea, kOptional, kNonNegative);
  io.table("sources", m.sources, Keywords{kMaterialGroups}, Text{});
}

}  // namespace coldspray::case_file
