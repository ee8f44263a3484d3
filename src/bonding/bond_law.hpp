// The evolution of the bonding parameter D_bond at a surface point in contact (thesis Chapter 4,
// Hirmand et al.): strain-based (eqs 4.3-4.5) or energy-based (eqs 4.16-4.17). SI units.
#pragma once

#include <Eigen/Core>

#include "case/case.hpp"

namespace coldspray::bonding {

struct BondLaw {
  case_file::BondingModel model = case_file::BondingModel::None;
  double critical_strain = 0.0;       // eps_c
  double critical_strain_rate = 0.0;  // 1/s
  double critical_energy = 0.0;       // G_c, J/m^2
  double critical_energy_rate = 0.0;  // Gdot_c, J/m^2/s
  double floor = 0.1;                 // lower bound of 1 - ln(rate ratio)
  double cell_size = 0.0;             // DCell of eq 4.17, m
  // Bonds form only between activated pairs (bodies::pair_activated); 0: always.
  double critical_penetration = 0.0;

  static BondLaw from_case(const case_file::Bonding& b, double cell_size);
  bool enabled() const { return model != case_file::BondingModel::None; }
};

// 1 - ln(ratio), the rate factor of eqs 4.4 and 4.16b, bounded below by `floor`: as written it
// turns negative once the rate exceeds e times the critical rate, which jetting always does.
double rate_factor(double ratio, double floor);

// The shear part of a plastic strain increment at a surface with unit normal n: the plastic
// strain increment tensor d_eps_p = 3/2 d_eqps s / sigma_vm (J2 flow), its traction-like vector
// on the surface t = d_eps_p n, and t's component in the surface plane, scaled by 2/sqrt(3) so
// that simple shear along the surface gives back d_eqps. Normal stretching gives 0.
double shear_plastic_strain_increment(double d_eqps, const Eigen::Matrix3d& deviatoric_stress,
                                      const Eigen::Vector3d& n);

// Eqs 4.3-4.5: dD = d_eps_s / eps_bond, eps_bond = eps_c (1 - ln(rate / rate_c)), rate =
// d_eps_s / dt.
double strain_bond_increment(const BondLaw& law, double d_shear_strain, double dt);

// Eqs 4.16-4.17: dG_s = sigma_vm d_eqps DCell, dD = dG_s / G_bond, G_bond = G_c (1 - ln(dG_s /
// (Gdot_c dt))).
double energy_bond_increment(const BondLaw& law, double von_mises, double d_eqps, double dt);

// The increment of D_bond over a step at a surface point in contact, by the law's model, from
// the point's Cauchy stress after the step, its plastic strain increment d_eqps > 0 and its
// outward contact normal n; in two parts, so that several laws of one model (a bond family,
// mpm/bond_shadows.hpp) share the first: the drive, which no parameter enters (the von Mises
// stress for the energy model, the shear plastic strain increment for the strain model), and the
// increment from it.
double bond_drive(case_file::BondingModel model, const Eigen::Matrix3d& stress, double d_eqps,
                  const Eigen::Vector3d& n);
double bond_increment_from_drive(const BondLaw& law, double drive, double d_eqps, double dt);
double bond_increment(const BondLaw& law, const Eigen::Matrix3d& stress, double d_eqps,
                      const Eigen::Vector3d& n, double dt);

}  // namespace coldspray::bonding
