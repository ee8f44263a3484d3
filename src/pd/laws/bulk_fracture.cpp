#include "pd/laws/bulk_fracture.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace coldspray::pd {
namespace {

// The bonds of one point whose other end lies above it (xi_z > 0), in spacings: each crosses the
// planes between the layers xi_z of them apart.
std::vector<Eigen::Vector3d> upward_bonds(double horizon_factor) {
  std::vector<Eigen::Vector3d> bonds;
  const int reach = static_cast<int>(std::floor(horizon_factor));
  for (int k = 1; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        const Eigen::Vector3d xi(i, j, k);
        if (xi.norm() <= horizon_factor) bonds.push_back(xi);
      }
  return bonds;
}

}  // namespace

ForceStretchCurve bulk_fracture_curve(double horizon_factor, int samples) {
  const std::vector<Eigen::Vector3d> bonds = upward_bonds(horizon_factor);
  // The stretch is in units of s_c; the bond stretches are linear in it to first order, so the
  // curve is computed at a small s_c, where that holds to 1e-6, and reported per s_c.
  const double s_c = 1e-6;
  std::vector<bool> broken(bonds.size(), false);
  auto traction = [&](double e) {
    double sum = 0.0;
    for (std::size_t b = 0; b < bonds.size(); ++b) {
      const Eigen::Vector3d& xi = bonds[b];
      const Eigen::Vector3d stretched(xi[0], xi[1], (1.0 + e) * xi[2]);
      const double s = stretched.norm() / xi.norm() - 1.0;
      if (s >= s_c) broken[b] = true;
      if (!broken[b]) sum += s * xi[2] * stretched[2] / stretched.norm();
    }
    return sum;
  };
  const double first = 1e-3 * s_c;
  const double slope = traction(first) / first;
  std::fill(broken.begin(), broken.end(), false);
  ForceStretchCurve curve;
  for (long n = 0;; ++n) {
    const double e = static_cast<double>(n) / samples;
    const double f = traction(e * s_c) / slope;
    curve.stretch.push_back(e);
    curve.force.push_back(f / s_c);
    if (n > 0 && std::all_of(broken.begin(), broken.end(), [](bool b) { return b; })) break;
  }
  return curve;
}

double work_of_fracture(const ForceStretchCurve& curve) {
  double work = 0.0;
  for (std::size_t n = 1; n < curve.stretch.size(); ++n)
    work += 0.5 * (curve.force[n] + curve.force[n - 1]) * (curve.stretch[n] - curve.stretch[n - 1]);
  return work;
}

InterfaceBondLaw scaled_law(const InterfaceBondLaw& fit_in_units_of_s_c, double s_c) {
  return {fit_in_units_of_s_c.yield_stretch * s_c, fit_in_units_of_s_c.softening / s_c};
}

double interface_work(const InterfaceBondLaw& law) {
  const double s_y = law.yield_stretch;
  return 0.5 * s_y * s_y + (1.0 - kBreakFraction) * s_y / law.softening;
}

InterfaceBondLaw fit_interface_law(const ForceStretchCurve& curve) {
  const auto peak = std::max_element(curve.force.begin(), curve.force.end());
  const double s_y = curve.stretch[static_cast<std::size_t>(peak - curve.force.begin())];
  // Equal works: s_y^2 / 2 + (1 - kBreakFraction) s_y / m = W.
  const double W = work_of_fracture(curve);
  return {s_y, (1.0 - kBreakFraction) * s_y / (W - 0.5 * s_y * s_y)};
}

}  // namespace coldspray::pd
