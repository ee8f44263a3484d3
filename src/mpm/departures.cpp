#include "mpm/departures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <vector>

#include "core/error.hpp"
#include "mpm/erase_indices.hpp"

namespace coldspray::mpm {

namespace {

bool is_gone(const std::vector<std::size_t>& gone, std::size_t p) {
  return std::binary_search(gone.begin(), gone.end(), p);
}

// Throws RunFault when the points `gone` would take more than kDepartedBulkFraction of a body's
// mass off the grid; the first such body in order is named.
void check_bulk_stays(const State& s, const std::vector<std::size_t>& gone) {
  const Points& P = s.points;
  std::vector<double> leaving(s.bodies.size(), 0.0);
  for (const std::size_t p : gone) leaving[P.body[p]] += P.mass[p];
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const BodyRange& r = s.bodies[b];
    if (leaving[b] == 0.0) continue;
    double on_grid = 0.0;
    for (std::size_t p = r.begin; p < r.end; ++p) on_grid += P.mass[p];
    const double fraction = (r.departed.mass + leaving[b]) / (r.departed.mass + on_grid);
    if (fraction > kDepartedBulkFraction)
      throw RunFault(fmt::format(
          "body '{}': {:.3g} % of its mass has left the grid by t = {:.6g} ns (a body losing more "
          "than {:.0f} % is not jetting: enlarge the grid, grid.min/grid.max)",
          r.name, 100.0 * fraction, s.time * 1e9, 100.0 * kDepartedBulkFraction));
  }
}

// What the points `gone` carry away, into their bodies' ledgers, in index order.
void book(State& s, const std::vector<std::size_t>& gone) {
  const Points& P = s.points;
  for (const std::size_t p : gone) {
    Departed& d = s.bodies[P.body[p]].departed;
    const double m = P.mass[p];
    const double v2 = P.velocity[0][p] * P.velocity[0][p] + P.velocity[1][p] * P.velocity[1][p] +
                      P.velocity[2][p] * P.velocity[2][p];
    ++d.points;
    d.mass += m;
    for (int k = 0; k < 3; ++k) d.momentum[k] += m * P.velocity[k][p];
    d.kinetic += 0.5 * m * v2;
    d.internal += P.energy[p] * P.volume0[p];
    d.plastic_work += P.plastic_work[p];
    d.viscous_work += P.viscous_work[p];
    d.contact_work += P.contact_work[p];
  }
  for (const AbsorbingPoint& a : s.absorbing)
    if (is_gone(gone, a.point)) s.bodies[P.body[a.point]].departed.absorbed += a.absorbed;
}

}  // namespace

void remove_departed_points(State& s) {
  Points& P = s.points;
  // The same test as the step's (update_stress.cpp), in index order: the set and its order do
  // not depend on the threads.
  std::vector<std::size_t> gone;
  gone.reserve(s.departing);
  for (std::size_t p = 0; p < P.size(); ++p)
    if (outside_domain(s.layout, P, p)) gone.push_back(p);
  assert(gone.size() == s.departing);
  s.departing = 0;
  check_bulk_stays(s, gone);
  book(s, gone);

  // Everything indexed by point. (s.max_signal_speed keeps the departed points' c + |v|: the
  // next step may be shorter than it need be.)
  P.for_each_array([&](auto& v) { erase_indices(v, gone); });
  for (auto& f : s.external_force) erase_indices(f, gone);
  erase_indices(s.gripped, gone);
  std::erase_if(s.absorbing, [&](const AbsorbingPoint& a) { return is_gone(gone, a.point); });
  for (AbsorbingPoint& a : s.absorbing) a.point = index_after(a.point, gone);
  for (BodyRange& b : s.bodies) {
    b.begin = index_after(b.begin, gone);
    b.end = index_after(b.end, gone);
  }
  s.bond_shadows.remove_points(gone);
  fit_scratch_to_points(s);
}

void fit_scratch_to_points(State& s) {
  // Rebuilt every step: only their lengths follow the points.
  const std::size_t n = s.points.size();
  for (auto& f : s.external_force) f.resize(n, 0.0);
  with_discretisation(s, [&]<class Shape, bool Axisymmetric>() {
    std::get<std::vector<Stencil<Shape, Axisymmetric>>>(s.stencils).resize(n);
  });
  s.blocks.order.resize(n);
  s.blocks.block_of.resize(n);
}

}  // namespace coldspray::mpm
