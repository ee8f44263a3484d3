#include "bonding/bond_law.hpp"

#include <algorithm>
#include <cmath>

#include "materials/symmetric_tensor.hpp"

namespace coldspray::bonding {

BondLaw BondLaw::from_case(const case_file::Bonding& b, double cell_size) {
  BondLaw law;
  law.model = b.model;
  law.critical_strain = b.critical_strain;
  law.critical_strain_rate = b.critical_strain_rate;
  law.critical_energy = b.critical_energy;
  law.critical_energy_rate = b.critical_energy_rate;
  law.floor = b.floor;
  law.cell_size = cell_size;
  law.critical_penetration = b.critical_penetration;
  return law;
}

double rate_factor(double ratio, double floor) { return std::max(1.0 - std::log(ratio), floor); }

double shear_plastic_strain_increment(double d_eqps, const Eigen::Matrix3d& deviatoric_stress,
                                      const Eigen::Vector3d& n) {
  const double von_mises = materials::von_mises_stress(deviatoric_stress);
  if (d_eqps <= 0.0 || von_mises == 0.0) return 0.0;
  const Eigen::Vector3d t = 1.5 * d_eqps / von_mises * (deviatoric_stress * n);
  return 2.0 / std::sqrt(3.0) * (t - t.dot(n) * n).norm();
}

double strain_bond_increment(const BondLaw& law, double d_shear_strain, double dt) {
  if (d_shear_strain <= 0.0) return 0.0;
  const double rate = d_shear_strain / dt;
  return d_shear_strain /
         (law.critical_strain * rate_factor(rate / law.critical_strain_rate, law.floor));
}

double energy_bond_increment(const BondLaw& law, double von_mises, double d_eqps, double dt) {
  const double dG = von_mises * d_eqps * law.cell_size;
  if (dG <= 0.0) return 0.0;
  return dG / (law.critical_energy * rate_factor(dG / (law.critical_energy_rate * dt), law.floor));
}

double bond_drive(case_file::BondingModel model, const Eigen::Matrix3d& stress, double d_eqps,
                  const Eigen::Vector3d& n) {
  switch (model) {
    case case_file::BondingModel::Strain: {
      const Eigen::Matrix3d deviator = stress - stress.trace() / 3.0 * Eigen::Matrix3d::Identity();
      return shear_plastic_strain_increment(d_eqps, deviator, n);
    }
    case case_file::BondingModel::Energy:
      return materials::von_mises_stress(stress);
    case case_file::BondingModel::None:
      break;
  }
  return 0.0;
}

double bond_increment_from_drive(const BondLaw& law, double drive, double d_eqps, double dt) {
  switch (law.model) {
    case case_file::BondingModel::Strain:
      return strain_bond_increment(law, drive, dt);
    case case_file::BondingModel::Energy:
      return energy_bond_increment(law, drive, d_eqps, dt);
    case case_file::BondingModel::None:
      break;
  }
  return 0.0;
}

double bond_increment(const BondLaw& law, const Eigen::Matrix3d& stress, double d_eqps,
                      const Eigen::Vector3d& n, double dt) {
  if (d_eqps <= 0.0) return 0.0;
  return bond_increment_from_drive(law, bond_drive(law.model, stress, d_eqps, n), d_eqps, dt);
}

}  // namespace coldspray::bonding
