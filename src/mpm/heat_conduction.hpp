// Heat conduction between material points (solver.heat_conduction), explicit on the grid as for
// momentum: the heat equation rho C_p dT/dt = div(k grad T) in its weak form on the nodes,
//   C_I dT_I/dt = Q_I,   C_I = sum_p N_I(x_p) m_p C_p,   Q_I = -sum_p V_p k_p grad T(x_p) . grad
//   N_I(x_p),
// with grad T(x_p) = sum_I T_I grad N_I(x_p) from the nodal temperatures T_I = sum_p N_I m_p C_p
// T_p / C_I, and each point's temperature then changed by the nodal increments it sees (FLIP), as
// the explicit MPM heat transfer of Tao et al. (Int. J. Numer. Meth. Eng. 2016) and Uintah's
// (Guilkey et al.). One field over all bodies: where bodies share nodes, heat crosses their
// interface (perfect thermal contact). The flux is zero on free surfaces (the weak form's natural
// condition), and in r-z the ring volumes V_p carry the 2 pi r of the divergence. Every point's
// heat change sum_p m_p C_p dT_p = dt sum_I Q_I is zero, as the gradients of the shape functions
// sum to zero: conduction moves internal energy and creates none (E += rho0 C_p dT per reference
// volume). As in those schemes, differences between the points of one cell carry no nodal
// gradient and do not conduct: the grid resolves temperature to about a cell (docs/mpm.md).
#pragma once

#include "mpm/phases.hpp"

namespace coldspray::mpm {

template <class Shape, bool Axisymmetric>
void conduct_heat(State& s) {
  if (!s.heat_conduction) return;
  std::vector<NodeHeat>& heat = s.grid.heat;
  Points& P = s.points;
  const long nodes = static_cast<long>(heat.size());
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) heat[n] = NodeHeat{};
  auto thermal = [&](std::size_t p) -> const materials::Thermal& {
    return s.bodies[P.body[p]].material.thermal;
  };
  // The nodal heat capacity and heat content.
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    const double mc = P.mass[p] * thermal(p).specific_heat, T = P.temperature[p];
    stencil_of<Shape, Axisymmetric>(s, p).for_each(
        s.layout, [&](std::size_t n, double w, double, double, double) {
          heat[n].capacity += w * mc;
          heat[n].temperature += w * mc * T;
        });
  });
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n)
    if (heat[n].capacity > 0.0) heat[n].temperature /= heat[n].capacity;
  // The heat flowing into each node from each point's Fourier flux -k grad T.
  for_each_point_by_block(s.blocks, [&](std::size_t p) {
    const auto& st = stencil_of<Shape, Axisymmetric>(s, p);
    double grad[3] = {0.0, 0.0, 0.0};
    st.for_each(s.layout, [&](std::size_t n, double, double gx, double gy, double gz) {
      grad[0] += heat[n].temperature * gx;
      grad[1] += heat[n].temperature * gy;
      grad[2] += heat[n].temperature * gz;
    });
    const double Vk = P.volume0[p] * P.J[p] * thermal(p).conductivity;
    st.for_each(s.layout, [&](std::size_t n, double, double gx, double gy, double gz) {
      heat[n].flow -= Vk * (grad[0] * gx + grad[1] * gy + grad[2] * gz);
    });
  });
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n)
    if (heat[n].capacity > 0.0) heat[n].flow *= s.dt / heat[n].capacity;  // now dT_I
  const long points = static_cast<long>(P.size());
#pragma omp parallel for schedule(static)
  for (long pi = 0; pi < points; ++pi) {
    const auto p = static_cast<std::size_t>(pi);
    double dT = 0.0;
    stencil_of<Shape, Axisymmetric>(s, p).for_each(
        s.layout, [&](std::size_t n, double w, double, double, double) { dT += w * heat[n].flow; });
    P.temperature[p] += dT;
    P.energy[p] += s.bodies[P.body[p]].material.density * thermal(p).specific_heat * dT;
  }
}

}  // namespace coldspray::mpm
