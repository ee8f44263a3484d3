// Artificial bulk viscosity for shock capturing: von Neumann-Richtmyer's quadratic term with
// Landshoff's linear term (the Wilkins form used by most explicit impact codes; see
// validation-data.md §4): q = rho l (c1 l (tr D)^2 - c0 c tr D) in compression, else 0.
#pragma once

namespace coldspray::materials {

// solver.artificial_viscosity (docs/input-reference.md).
struct ArtificialViscosity {
  bool enabled = true;
  double linear = 0.06;    // c0 in q = rho l (c1 l (tr D)^2 - c0 c tr D)
  double quadratic = 1.5;  // c1

  friend bool operator==(const ArtificialViscosity&, const ArtificialViscosity&) = default;
};

// rho: density, l: cell size (MPM) or point spacing (PD), c: sound speed, trace_D: volumetric
// strain rate (1/s).
inline double bulk_viscous_pressure(const ArtificialViscosity& av, double rho, double l, double c,
                                    double trace_D) {
  if (!av.enabled || trace_D >= 0.0) return 0.0;
  return rho * l * (av.quadratic * l * trace_D * trace_D - av.linear * c * trace_D);
}

}  // namespace coldspray::materials
