// A material as a composition of independent sub-models (strength, shear modulus, melting
// temperature, equation of state, heating), each a plain parameter struct chosen by name: its
// kName, which the material schema's lists of names are made of (case/material_schema.hpp).
// All values SI. The kernels that use these live beside them (strength/, shear_modulus/, ...).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <variant>

namespace coldspray::materials {

// Isotropic elastic constants at the reference state.
struct Elastic {
  double shear_modulus = 0.0;  // G, Pa
  double bulk_modulus = 0.0;   // K, Pa
};

namespace strength {
// No plasticity: the deviatoric response stays elastic.
struct Elastic {
  static constexpr std::string_view kName = "elastic";
};
// J2 plasticity with linear isotropic hardening: sigma_y = yield_stress + H eqps.
struct VonMises {
  static constexpr std::string_view kName = "von-mises";
  double yield_stress = 0.0;       // Pa
  double hardening_modulus = 0.0;  // H, Pa
};
// Johnson-Cook (thesis eq 2.3): (A + B eps^n)(1 + C ln(rate/rate0))(1 - T*^m),
// T* = (T - T_ref)/(T_m - T_ref) with T_m from the material's melt model.
struct JohnsonCook {
  static constexpr std::string_view kName = "johnson-cook";
  double A = 0.0;                        // Pa
  double B = 0.0;                        // Pa
  double n = 1.0;                        // -
  double C = 0.0;                        // -
  double m = 1.0;                        // -
  double reference_strain_rate = 1.0;    // 1/s
  double reference_temperature = 298.0;  // K
};
// Preston-Tonks-Wallace (thesis eqs 2.4-2.8; Preston, Tonks & Wallace, J. Appl. Phys. 93 (2003)
// 211). Dimensionless except atomic_mass. `s1` is the overdriven-shock exponent (PTW's beta).
struct Ptw {
  static constexpr std::string_view kName = "ptw";
  double theta = 0.0;        // strain hardening rate
  double p = 0.0;            // strain hardening constant (thesis "d")
  double s0 = 0.0;           // saturation stress at 0 K
  double s_inf = 0.0;        // saturation stress at melting
  double kappa = 0.0;        // temperature dependence
  double gamma = 0.0;        // strain rate dependence
  double y0 = 0.0;           // yield stress at 0 K
  double y_inf = 0.0;        // yield stress at melting
  double y1 = 0.0;           // medium strain rate constant
  double y2 = 0.0;           // medium strain rate exponent
  double s1 = 0.0;           // high strain rate exponent (PTW beta)
  double atomic_mass = 0.0;  // M, kg
};
using Model = std::variant<Elastic, VonMises, JohnsonCook, Ptw>;
}  // namespace strength

namespace shear_modulus {
// G from the material's elastic constants at all temperatures.
struct Constant {
  static constexpr std::string_view kName = "constant";
};
// Mechanical Threshold Stress form (thesis eq 2.6): mu(T) = mu0 - D / (exp(T0/T) - 1).
struct Mts {
  static constexpr std::string_view kName = "mts";
  double mu0 = 0.0;  // Pa, shear modulus at 0 K
  double D = 0.0;    // Pa
  double T0 = 0.0;   // K
};
using Model = std::variant<Constant, Mts>;
}  // namespace shear_modulus

namespace melt {
struct Constant {
  static constexpr std::string_view kName = "constant";
  double temperature = 0.0;  // K
};
// Steinberg-Cochran-Guinan (thesis eq 2.9; Steinberg et al., J. Appl. Phys. 51 (1980) 1498).
struct Scg {
  static constexpr std::string_view kName = "scg";
  double Tm0 = 0.0;     // K, fit constant at eta = 1
  double a = 0.0;       // first-order volume correction to Gruneisen's gamma
  double gamma0 = 0.0;  // Gruneisen gamma at the reference state
};
using Model = std::variant<Constant, Scg>;
}  // namespace melt

namespace eos {
// p = K mu, mu = rho/rho0 - 1, with K the material's bulk modulus.
struct Linear {
  static constexpr std::string_view kName = "linear";
};
// Mie-Gruneisen with a linear Us-up Hugoniot reference (thesis §3.5.2, eqs 3.39-3.43).
struct MieGruneisen {
  static constexpr std::string_view kName = "mie-gruneisen";
  double c0 = 0.0;      // m/s, bulk sound speed (Us intercept)
  double s = 0.0;       // Us-up slope
  double gamma0 = 0.0;  // Gruneisen gamma
};
using Model = std::variant<Linear, MieGruneisen>;
}  // namespace eos

// Adiabatic heating (thesis eq 3.44).
struct Thermal {
  double specific_heat = 0.0;   // C_p, J/(kg K)
  double taylor_quinney = 0.9;  // chi, fraction of plastic work turned into heat
  double conductivity = 0.0;    // k, W/(m K), for solver.heat_conduction (0: none)
};

struct Material {
  std::string name;
  std::string description;
  double density = 0.0;  // rho0, kg/m^3
  Elastic elastic;
  strength::Model strength;
  shear_modulus::Model shear_modulus;
  melt::Model melt;
  eos::Model eos;
  Thermal thermal;
  // The solid's surface energy gamma, J/m^2 (0: not given): contact model 2 takes the interface's
  // fracture energy as gamma_a + gamma_b, the work of separating a metallic bond.
  double surface_energy = 0.0;
  // Where each group's numbers come from, by group name ("strength", "eos", ...).
  std::map<std::string, std::string> sources;
};

}  // namespace coldspray::materials
