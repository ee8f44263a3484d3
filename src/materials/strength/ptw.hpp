// Preston-Tonks-Wallace flow stress (thesis eqs 2.4-2.8; Preston, Tonks & Wallace,
// J. Appl. Phys. 93 (2003) 211), in SI throughout.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "materials/material.hpp"
#include "materials/strength/conditions.hpp"

namespace coldspray::materials::strength {

// Floor on the plastic strain rate inside PTW, 1/s: ln(gamma xi_dot / rate) diverges at rest.
// The yield check evaluates the flow stress at rest, i.e. here: the least flow stress any plastic
// step can have. In the consistent return it acts only on increments below 1e-6 dt, negligible.
// Where the erf of eq 2.7 is not saturated (small kappa T/Tm, e.g. cu-ptw at room temperature)
// the at-rest flow stress depends on the floor, logarithmically.
inline constexpr double kPtwMinStrainRate = 1e-6;

// Eq 2.8: the reciprocal time for a transverse wave to cross an atom,
// xi_dot = (1/2) (4 pi rho / (3 M))^(1/3) (mu / rho)^(1/2). In SI (rho kg/m^3, M kg, mu Pa) the
// result is in 1/s with no conversion factor (the thesis' code needed its um/us/ng/MPa set).
// Eq 2.7 uses ln(gamma xi_dot), taken from eq 2.8 raised to the sixth power,
// (gamma xi_dot)^6 = gamma^6 (4 pi / (3 M))^2 mu^3 / (64 rho): one log where the direct form
// takes a cube root, a square root and a log. (Al at rest: about 6e49, far from overflow.)
inline double ptw_atomic_rate_sixth_power(const Ptw& p, double density, double shear_modulus) {
  const double g2 = p.gamma * p.gamma;
  const double k = 4.0 * std::numbers::pi / (3.0 * p.atomic_mass);
  return g2 * g2 * g2 * k * k * shear_modulus * shear_modulus * shear_modulus / (64.0 * density);
}

inline double ptw_log_atomic_rate(const Ptw& p, double density, double shear_modulus) {
  return std::log(ptw_atomic_rate_sixth_power(p, density, shear_modulus)) / 6.0;
}

// PTW within one step: the terms of eqs 2.7-2.8 that depend only on the step's conditions
// (T/Tm and ln(gamma xi_dot), whose cube root dominates an evaluation) are taken once, so the
// consistent return's iterations evaluate only what depends on the strain and the rate.
class PtwStep {
 public:
  PtwStep(const Ptw& p, const Conditions& c)
      : p_(p),
        mu_(c.shear_modulus),
        T_hat_(c.temperature / c.melt_temperature),
        ln_gamma_xi_(ptw_log_atomic_rate(p, c.density, c.shear_modulus)) {}

  double operator()(double eqps, double rate) const {
    if (T_hat_ >= 1.0) return 0.0;  // melted: no strength
    // ln of the dimensionless rate r = rate/(gamma xi_dot); the powers of r below as exp(k ln r).
    const double ln_r = std::log(std::max(rate, kPtwMinStrainRate)) - ln_gamma_xi_;
    const double thermal = std::erf(-p_.kappa * T_hat_ * ln_r);
    const double overdriven = p_.s0 * std::exp(p_.s1 * ln_r);
    // Eq 2.7a/b: thermal activation against the overdriven-shock power laws.
    const double tau_s = std::max(p_.s0 - (p_.s0 - p_.s_inf) * thermal, overdriven);
    const double tau_y = std::max(p_.y0 - (p_.y0 - p_.y_inf) * thermal,
                                  std::min(p_.y1 * std::exp(p_.y2 * ln_r), overdriven));
    // tau_s <= tau_y: saturated, eq 2.4's limit beta -> 0 for eqps > 0 (and below it, eq 2.4
    // would soften with strain).
    if (tau_s <= tau_y) return 2.0 * tau_s * mu_;
    // Eqs 2.4-2.5 rewritten exactly as tau = tau_y + alpha ln(1 + psi (1 - exp(-w/psi))),
    // w = theta eqps / alpha, so expm1/log1p keep it accurate near eqps = 0 and near saturation.
    const double alpha = (p_.s0 - tau_y) / p_.p;
    const double psi = std::expm1((tau_s - tau_y) / alpha);
    const double w = p_.theta * eqps / alpha;
    // beta > ~709 overflows psi; its limit psi (1 - exp(-w/psi)) -> w.
    const double hardening = std::isinf(psi) ? w : -psi * std::expm1(-w / psi);
    return 2.0 * (tau_y + alpha * std::log1p(hardening)) * mu_;
  }

 private:
  const Ptw& p_;
  double mu_, T_hat_, ln_gamma_xi_;
};

inline PtwStep prepare(const Ptw& p, const Conditions& c) { return PtwStep(p, c); }

inline double flow_stress(const Ptw& p, double eqps, double rate, const Conditions& c) {
  return PtwStep(p, c)(eqps, rate);
}

}  // namespace coldspray::materials::strength
