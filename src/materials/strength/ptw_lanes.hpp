// PtwStep (ptw.hpp) for four points at once: the same equations (thesis eqs 2.4-2.8), lane by
// lane, with libmvec's vector log/exp/erf/expm1/log1p (core/simd.hpp). A lane's result differs
// from PtwStep's only by the vector functions' rounding (a few ulp).
#pragma once

#include "core/simd.hpp"

#if COLDSPRAY_HAVE_SIMD

#include "materials/strength/ptw.hpp"

namespace coldspray::materials::strength {

class PtwLanes {
 public:
  using Doubles = simd::Doubles;

  // Lane i under the conditions c[i] of its point.
  COLDSPRAY_SIMD_TARGET PtwLanes(const Ptw& p, const Conditions (&c)[simd::kLanes]) : p_(p) {
    Doubles atomic_rate_power;  // (gamma xi_dot)^6 of each lane
    for (int i = 0; i < simd::kLanes; ++i) {
      mu_[i] = c[i].shear_modulus;
      T_hat_[i] = c[i].temperature / c[i].melt_temperature;
      atomic_rate_power[i] = ptw_atomic_rate_sixth_power(p, c[i].density, mu_[i]);
    }
    ln_gamma_xi_ = simd::log(atomic_rate_power) / 6.0;
  }

  // The flow stress of each lane at its (eqps, rate): PtwStep::operator() lane by lane.
  COLDSPRAY_SIMD_TARGET Doubles operator()(Doubles eqps, Doubles rate) const {
    using simd::broadcast;
    const Doubles ln_r = simd::log(simd::max(rate, broadcast(kPtwMinStrainRate))) - ln_gamma_xi_;
    const Doubles thermal = simd::erf(-p_.kappa * T_hat_ * ln_r);
    const Doubles overdriven = p_.s0 * simd::exp(p_.s1 * ln_r);
    // Eq 2.7a/b.
    const Doubles tau_s = simd::max(p_.s0 - (p_.s0 - p_.s_inf) * thermal, overdriven);
    const Doubles tau_y = simd::max(p_.y0 - (p_.y0 - p_.y_inf) * thermal,
                                    simd::min(p_.y1 * simd::exp(p_.y2 * ln_r), overdriven));
    const auto saturated = tau_s <= tau_y;
    const auto melted = T_hat_ >= 1.0;
    Doubles tau = tau_s;
    // Eqs 2.4-2.5 in PtwStep's cancellation-free form, only if some lane hardens. (In the other
    // lanes psi <= 0 may make -w/psi a NaN; those lanes keep tau_s.)
    if (simd::any(~saturated & ~melted)) {
      const Doubles alpha = (p_.s0 - tau_y) / p_.p;
      const Doubles psi = simd::expm1((tau_s - tau_y) / alpha);
      const Doubles w = p_.theta * eqps / alpha;
      const Doubles hardening = psi == __builtin_inf() ? w : -psi * simd::expm1(-w / psi);
      tau = saturated ? tau_s : tau_y + alpha * simd::log1p(hardening);
    }
    return melted ? broadcast(0.0) : 2.0 * tau * mu_;
  }

 private:
  const Ptw& p_;
  Doubles mu_, T_hat_, ln_gamma_xi_;
};

COLDSPRAY_SIMD_TARGET inline PtwLanes prepare_lanes(const Ptw& p,
                                                    const Conditions (&c)[simd::kLanes]) {
  return PtwLanes(p, c);
}

}  // namespace coldspray::materials::strength

#endif
