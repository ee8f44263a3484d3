#include "bonding/cohesive_law.hpp"

#include <cmath>

namespace coldspray::bonding {

CohesiveLaw CohesiveLaw::from_case(const case_file::Bonding& b) {
  CohesiveLaw law;
  law.enabled =
      b.model != case_file::BondingModel::None && b.debond.law == case_file::DebondLaw::Cohesive;
  law.strength = b.debond.strength;
  law.fracture_energy = b.debond.fracture_energy.value_or(b.critical_energy);
  law.shear_ratio = b.debond.shear_ratio;
  return law;
}

double effective_traction(const Eigen::Vector3d& t, const Eigen::Vector3d& n, double beta) {
  const double normal = t.dot(n);
  const double tension = std::max(normal, 0.0);
  const double shear = (t - normal * n).norm() / beta;
  return std::sqrt(tension * tension + shear * shear);
}

double effective_opening(const Eigen::Vector3d& u, const Eigen::Vector3d& n, double beta) {
  const double normal = u.dot(n);
  const double opening = std::max(normal, 0.0);
  const double sliding = beta * (u - normal * n).norm();
  return std::sqrt(opening * opening + sliding * sliding);
}

}  // namespace coldspray::bonding
