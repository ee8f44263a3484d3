// PTW flow stress (thesis eqs 2.4-2.8) for the al-ptw parameters, against hand calculations
// written out below in the thesis' own form, independent of src/materials/strength/ptw.hpp
// (which uses an algebraically rearranged, cancellation-free form). Numbers in comments come from
// a separate 40-digit evaluation (mpmath) of the same equations.
#include "materials/strength/ptw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "materials/flow_stress.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

using namespace testing::al_eos;

// Eq 2.6, Al MTS constants.
double mts_hand(double T) { return 28.8e9 - 3.44e9 / (std::exp(215.0 / T) - 1.0); }

// Eqs 2.4, 2.5, 2.7 and 2.8 as printed, with the saturated limit for tau_s <= tau_y.
double ptw_hand(double eps, double rate, double T, double Tm, double mu) {
  const double gamma = 2.04e-5, theta = 0.01156, p = 3.0, y0 = 0.0115, y_inf = 0.002003,
               y1 = 0.0168, y2 = 0.2339, s1 = 0.2034, s0 = 0.01489, s_inf = 0.002819, kappa = 1.3,
               M = 4.48039e-26;
  const double T_hat = T / Tm;
  const double xi = 0.5 * std::pow(4.0 * std::numbers::pi * kRho0 / (3.0 * M), 1.0 / 3.0) *
                    std::pow(mu / kRho0, 0.5);
  const double e = std::erf(kappa * T_hat * std::log(gamma * xi / rate));
  const double tau_s = std::max(s0 - (s0 - s_inf) * e, s0 * std::pow(rate / (gamma * xi), s1));
  const double tau_y = std::max(
      y0 - (y0 - y_inf) * e,
      std::min(y1 * std::pow(rate / (gamma * xi), y2), s0 * std::pow(rate / (gamma * xi), s1)));
  if (tau_s <= tau_y) return 2.0 * tau_s * mu;
  const double alpha = (s0 - tau_y) / p;
  const double beta = (tau_s - tau_y) / alpha;
  const double psi = std::exp(beta) - 1.0;
  const double tau =
      tau_s + alpha * std::log(1.0 - psi * std::exp(-beta - theta * eps / (alpha * psi)));
  return 2.0 * tau * mu;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// eqps 0.5, 1e7 1/s, 298 K, rho0, M = 4.48039e-26 kg (26.9815 u). Step by step:
//   mu(298 K)  = 28.8e9 - 3.44e9/(exp(215/298) - 1) = 25.546949071397262e9 Pa   (eq 2.6)
//   Tm         = 1220 K (SCG at eta = 1),  T_hat = 0.24426229508196721
//   xi_dot     = 0.5 (4 pi 2700/(3 M))^(1/3) (mu/2700)^(1/2) = 9.7200797483112844e12 1/s (2.8)
//   rate/(gamma xi_dot) = 0.05043128154545611,  erf(kappa T_hat ln(gamma xi_dot/rate))
//              = 0.82022199779560028
//   tau_s      = max(0.004989100264609309, s0 r^s1 = 0.0081100564786662948)
//              = 0.0081100564786662948
//   tau_y      = max(0.0037103516869351841, min(y1 r^y2 = 0.008353544928893156,
//                    0.0081100564786662948)) = 0.0081100564786662948
//   tau_s <= tau_y: saturated, tau = tau_s (eqps has no effect at this rate). At 298 K al-ptw is
//   saturated from about 3.8e6 to 2.0e8 1/s (y1 r^y2 >= s0 r^s1 needs r >= 0.0191).
//   sigma_y    = 2 tau mu = 414.37439965328649e6 Pa
TEST(MaterialsPtw, AlFlowStressAt1e7PerSecondMatchesHandCalculation) {
  const double mu = mts_hand(298.0);
  EXPECT_LT(rel(mu, 25.546949071397262e9), 1e-14);
  const double hand = ptw_hand(0.5, 1e7, 298.0, 1220.0, mu);
  EXPECT_LT(rel(hand, 414.37439965328649e6), 1e-12);
  const double code = flow_stress(testing::al_ptw(), 0.5, 1e7, 298.0, kRho0);
  EXPECT_LT(rel(code, hand), 1e-12) << code;
  // Saturated: no strain hardening at this rate.
  EXPECT_EQ(flow_stress(testing::al_ptw(), 0.0, 1e7, 298.0, kRho0), code);
}

// The kernel directly, with the conditions spelt out: same number.
TEST(MaterialsPtw, KernelMatchesPublicFunction) {
  const Material m = testing::al_ptw();
  const auto& ptw = std::get<strength::Ptw>(m.strength);
  const double mu = mts_hand(298.0);
  const double code = strength::flow_stress(ptw, 0.5, 1e7, {298.0, kRho0, mu, 1220.0});
  EXPECT_LT(rel(code, 414.37439965328649e6), 1e-12);
}

// 1e3 1/s (r = 5.043128154545611e-6, erf = 0.99999995687045787): both tau_s and tau_y on their
// thermal (erf) branches (tau_s = 0.002819000520616703 > s0 r^s1 = 0.0012457298717588702,
// tau_y = 0.0020030004096012616 > y1 r^y2 = 0.00096888183304195863), tau_s > tau_y, so eq 2.4's
// hardening is active. alpha = 0.0042956665301329128, beta = 0.18995890516440844,
// psi = 0.20919990476491418. eqps 0.02: tau = 0.0022021648811828356,
// sigma_y = 112.517188132795e6 Pa. eqps 0: sigma_y = 2 tau_y mu = 102.34109890814257e6 Pa;
// eqps 0.5: tau = 0.0028178042259574327, sigma_y = 143.97260210740503e6 Pa.
TEST(MaterialsPtw, LowRateUsesThermalBranchesAndHardens) {
  const Material m = testing::al_ptw();
  const double mu = mts_hand(298.0);
  const double cases[][3] = {{0.0, 102.34109890814257e6, 0.0},
                             {0.02, 112.517188132795e6, 0.0},
                             {0.5, 143.97260210740503e6, 0.0}};
  for (const auto& c : cases) {
    const double hand = ptw_hand(c[0], 1e3, 298.0, 1220.0, mu);
    EXPECT_LT(rel(hand, c[1]), 1e-11) << "eqps " << c[0];
    EXPECT_LT(rel(flow_stress(m, c[0], 1e3, 298.0, kRho0), hand), 1e-12) << "eqps " << c[0];
  }
}

// 1e5 1/s (r = 5.043128154545611e-4, erf = 0.99934914624229408): the max of eq 2.7a switches to
// s0 r^s1 (0.0031785121703599246 > thermal 0.0028268564557092681) and the min of eq 2.7b picks
// y1 r^y2 (0.0028449249415589788, above the thermal 0.0020091811581369331); still tau_s > tau_y.
// alpha = 0.0040150250194803404, beta = 0.083084719816794952, psi = 0.086633864070606758.
// eqps 0.02: tau = 0.0030103653781249579, sigma_y = 153.81130200251172e6 Pa.
TEST(MaterialsPtw, MediumRateUsesPowerLawBranches) {
  const double mu = mts_hand(298.0);
  const double hand = ptw_hand(0.02, 1e5, 298.0, 1220.0, mu);
  EXPECT_LT(rel(hand, 153.81130200251172e6), 1e-11);
  EXPECT_LT(rel(flow_stress(testing::al_ptw(), 0.02, 1e5, 298.0, kRho0), hand), 1e-12);
}

// 1e10 1/s, overdriven (rate/(gamma xi_dot) = 50.43128154545611 > 1): the erf argument is
// negative (erf = -0.92169930378951006), s0 r^s1 = 0.033053989032903757 beats the thermal
// 0.026015832296043176 in eq 2.7a, the min of eq 2.7b switches to s0 r^s1 (y1 r^y2 =
// 0.042031105482951882), tau_y = tau_s = 0.033053989032903757 (saturated),
// sigma_y = 1.6888571488602318e9 Pa.
TEST(MaterialsPtw, OverdrivenRateIsSaturatedPowerLaw) {
  const double mu = mts_hand(298.0);
  const double hand = ptw_hand(0.5, 1e10, 298.0, 1220.0, mu);
  EXPECT_LT(rel(hand, 1.6888571488602318e9), 1e-11);
  const Material m = testing::al_ptw();
  EXPECT_LT(rel(flow_stress(m, 0.5, 1e10, 298.0, kRho0), hand), 1e-12);
  // Saturated: no strain hardening left.
  EXPECT_EQ(flow_stress(m, 0.0, 1e10, 298.0, kRho0), flow_stress(m, 2.0, 1e10, 298.0, kRho0));
}

// tau_s <= tau_y is eq 2.4's beta -> 0 limit: approaching it from tau_s > tau_y (beta small)
// the formula's value tends to tau_s for eqps > 0, so the saturated branch is continuous.
TEST(MaterialsPtw, SaturatedLimitIsContinuous) {
  strength::Ptw p = std::get<strength::Ptw>(testing::al_ptw().strength);
  const double mu = mts_hand(298.0);
  const strength::Conditions c{298.0, kRho0, mu, 1220.0};
  // At 1e3 1/s both are on the thermal branch, erf = 0.99999995687045787 (see above); with
  // y0 = s0, tau_s - tau_y = (s_inf - y_inf) erf.
  p.y0 = p.s0;
  p.y_inf = p.s_inf - 1e-9;  // tau_s barely above tau_y
  const double just_above = strength::flow_stress(p, 0.5, 1e3, c);
  p.y_inf = p.s_inf + 1e-9;  // tau_y above tau_s: saturated
  const double saturated = strength::flow_stress(p, 0.5, 1e3, c);
  const double tau_s = p.s0 - (p.s0 - p.s_inf) * 0.99999995687045787;
  EXPECT_LT(rel(saturated, 2.0 * mu * tau_s), 1e-12);
  EXPECT_LT(rel(just_above, saturated), 1e-9);
  // Exactly equal: no division by zero.
  p.y_inf = p.s_inf;
  EXPECT_LT(rel(strength::flow_stress(p, 0.5, 1e3, c), saturated), 1e-12);
}

// A huge beta (p = 2e4, beta ~ 1270) overflows exp(beta); the code then takes the formula's
// limit tau = tau_y + alpha ln(1 + theta eqps/alpha), which for beta ~ 630 (p = 1e4, still
// finite) the formula itself already equals to double precision.
TEST(MaterialsPtw, HugeBetaTakesTheOverflowLimit) {
  strength::Ptw p = std::get<strength::Ptw>(testing::al_ptw().strength);
  const double mu = mts_hand(298.0);
  const strength::Conditions c{298.0, kRho0, mu, 1220.0};
  const double tau_y = 0.0020030004096012616;  // thermal branch at 1e3 1/s, see above
  auto limit = [&](double p_value) {
    const double alpha = (p.s0 - tau_y) / p_value;
    return 2.0 * mu * (tau_y + alpha * std::log(1.0 + p.theta * 0.5 / alpha));
  };
  p.p = 2e4;
  const double overflowed = strength::flow_stress(p, 0.5, 1e3, c);
  ASSERT_TRUE(std::isfinite(overflowed));
  EXPECT_LT(rel(overflowed, limit(2e4)), 1e-12);
  p.p = 1e4;
  EXPECT_LT(rel(strength::flow_stress(p, 0.5, 1e3, c), limit(1e4)), 1e-12);
}

// At and above Tm (SCG, 1220 K at rho0) the flow stress is zero; compression raises Tm (eq 2.9)
// and restores strength at the same temperature.
TEST(MaterialsPtw, ZeroAtMelt) {
  const Material m = testing::al_ptw();
  EXPECT_EQ(flow_stress(m, 0.5, 1e7, 1220.0, kRho0), 0.0);
  EXPECT_EQ(flow_stress(m, 0.5, 1e7, 1500.0, kRho0), 0.0);
  EXPECT_GT(flow_stress(m, 0.5, 1e7, 1219.0, kRho0), 0.0);
  EXPECT_GT(flow_stress(m, 0.5, 1e7, 1300.0, 1.1 * kRho0), 0.0);
}

// Non-decreasing in plastic strain and in strain rate across all branches, at several
// temperatures; strictly increasing in eqps where tau_s > tau_y.
TEST(MaterialsPtw, MonotoneInStrainAndRate) {
  const Material m = testing::al_ptw();
  for (const double T : {100.0, 298.0, 600.0, 900.0, 1200.0}) {
    for (double log_rate = -8.0; log_rate <= 12.0; log_rate += 0.25) {
      const double rate = std::pow(10.0, log_rate);
      double previous = 0.0;
      for (double eps = 0.0; eps <= 3.0; eps += 0.01) {
        const double s = flow_stress(m, eps, rate, T, kRho0);
        ASSERT_GE(s, previous) << "T " << T << " rate " << rate << " eqps " << eps;
        ASSERT_GE(flow_stress(m, eps, 1.5 * rate, T, kRho0), s)
            << "T " << T << " rate " << rate << " eqps " << eps;
        previous = s;
      }
    }
  }
  EXPECT_GT(flow_stress(m, 0.02, 1e3, 298.0, kRho0), flow_stress(m, 0.01, 1e3, 298.0, kRho0));
}

// Below the rate floor (1e-6 1/s) the flow stress no longer changes, and rate 0 is finite. At
// 50 K the erf of eq 2.7 is not yet saturated at these rates, so the floor's value shows: rate 0
// gives the hand value at exactly 1e-6 1/s, and 1e-5 1/s is stronger.
TEST(MaterialsPtw, RateFloor) {
  const Material m = testing::al_ptw();
  EXPECT_EQ(strength::kPtwMinStrainRate, 1e-6);
  const double at_rest = flow_stress(m, 0.1, 0.0, 50.0, kRho0);
  EXPECT_LT(rel(at_rest, ptw_hand(0.1, 1e-6, 50.0, 1220.0, mts_hand(50.0))), 1e-12);
  EXPECT_EQ(flow_stress(m, 0.1, 1e-9, 50.0, kRho0), at_rest);
  EXPECT_GT(flow_stress(m, 0.1, 1e-5, 50.0, kRho0), at_rest * (1.0 + 1e-3));
  // Quasi-static strength at room temperature: between 2 y_inf mu and 2 s_inf mu.
  const double room = flow_stress(m, 0.1, 0.0, 298.0, kRho0);
  EXPECT_GT(room, 2.0 * 0.002003 * mts_hand(298.0));
  EXPECT_LT(room, 2.0 * 0.002819 * mts_hand(298.0));
}

}  // namespace
}  // namespace coldspray::materials
