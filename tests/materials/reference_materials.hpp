// The built-in materials' parameters written out as structs (values of data/materials/*.yaml),
// so the material-model tests do not depend on the case-file parser, plus small test materials.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials::testing {

// Aluminium's density and Mie-Gruneisen constants (al-ptw and al-jc), for the hand calculations.
namespace al_eos {
inline constexpr double kRho0 = 2700.0, kC0 = 5386.0, kS = 1.339, kGamma0 = 1.97;
}  // namespace al_eos

// data/materials/al-ptw.yaml.
inline Material al_ptw() {
  Material m;
  m.name = "al-ptw";
  m.density = 2700.0;
  m.elastic = {26.0e9, 66.4e9};
  m.strength = strength::Ptw{.theta = 0.01156,
                             .p = 3.0,
                             .s0 = 0.01489,
                             .s_inf = 0.002819,
                             .kappa = 1.3,
                             .gamma = 2.04e-5,
                             .y0 = 0.0115,
                             .y_inf = 0.002003,
                             .y1 = 0.0168,
                             .y2 = 0.2339,
                             .s1 = 0.2034,
                             .atomic_mass = 4.48039e-26};
  m.shear_modulus = shear_modulus::Mts{.mu0 = 28.8e9, .D = 3.44e9, .T0 = 215.0};
  m.melt = melt::Scg{.Tm0 = 1220.0, .a = 1.5, .gamma0 = 1.97};
  m.eos = eos::MieGruneisen{.c0 = 5386.0, .s = 1.339, .gamma0 = 1.97};
  m.thermal = {.specific_heat = 896.0, .taylor_quinney = 0.9};
  return m;
}

// data/materials/cu-jc.yaml.
inline Material cu_jc() {
  Material m;
  m.name = "cu-jc";
  m.density = 8930.0;
  m.elastic = {46.0e9, 129.0e9};
  m.strength = strength::JohnsonCook{.A = 90e6,
                                     .B = 292e6,
                                     .n = 0.31,
                                     .C = 0.025,
                                     .m = 1.09,
                                     .reference_strain_rate = 1.0,
                                     .reference_temperature = 298.0};
  m.shear_modulus = shear_modulus::Constant{};
  m.melt = melt::Constant{1356.0};
  m.eos = eos::MieGruneisen{.c0 = 3940.0, .s = 1.489, .gamma0 = 2.02};
  m.thermal = {.specific_heat = 383.0, .taylor_quinney = 0.9};
  return m;
}

// Linear hardening, constant G, linear EOS: the textbook elastic-plastic solid.
inline Material linear_hardening() {
  Material m;
  m.name = "linear-hardening";
  m.density = 8930.0;
  m.elastic = {46.0e9, 129.0e9};
  m.strength = strength::VonMises{.yield_stress = 400e6, .hardening_modulus = 100e6};
  m.shear_modulus = shear_modulus::Constant{};
  m.melt = melt::Constant{1356.0};
  m.eos = eos::Linear{};
  m.thermal = {.specific_heat = 383.0, .taylor_quinney = 0.9};
  return m;
}

// al-ptw's elastic constants and EOS with no plasticity.
inline Material al_elastic() {
  Material m = al_ptw();
  m.name = "al-elastic";
  m.strength = strength::Elastic{};
  m.shear_modulus = shear_modulus::Constant{};
  return m;
}

}  // namespace coldspray::materials::testing
