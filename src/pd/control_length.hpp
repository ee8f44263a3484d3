#pragma once

#include <cmath>

#include "case/case.hpp"
#include "pd/deformation.hpp"
#include "pd/families.hpp"

namespace coldspray::pd {

// The length l of the zero-energy-mode control (docs/pd.md, "Zero-energy modes"). Silling's
// penalty (CMAME 322 (2017) 42) weighs a bond by c / |xi|; the control here weighs every bond
// of a body by c / l, l the length at which a full family's sum of omega beta / l equals its
// sum of omega beta / |xi| (family sums over the cubic lattice of spacing h the bodies are
// seeded on). So the penalty keeps Silling's stiffness on average, and its bond weights are
// those of the second-order fit it measures z against (omega beta V_j): the fit minimises
// sum_j omega beta V_j |z|^2, so the penalty is the gradient of the stored energy
// 1/2 sum_i V_i sum_j (G_s c / l) omega beta V_j |z_ij|^2 (the envelope theorem) and gives back
// no more than it took. With c / |xi| it is not a gradient and fed energy in.
inline double control_length(case_file::Influence kind, double delta, double h) {
  const int reach = static_cast<int>(std::ceil((delta + 0.5 * h) / h));
  double weight = 0.0, weight_per_length = 0.0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b)
      for (int c = -reach; c <= reach; ++c) {
        const double r = h * std::sqrt(static_cast<double>(a * a + b * b + c * c));
        if (r == 0.0) continue;
        const double omega = kind == case_file::Influence::Constant
                                 ? influence<case_file::Influence::Constant>(r, delta)
                                 : influence<case_file::Influence::InverseDistance>(r, delta);
        const double w = omega * volume_fraction(r, delta, h);
        weight += w;
        weight_per_length += w / r;
      }
  return weight / weight_per_length;
}

}  // namespace coldspray::pd
