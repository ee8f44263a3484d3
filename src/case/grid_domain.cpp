#include "case/grid_domain.hpp"

namespace coldspray::case_file {

std::pair<Vec3, Vec3> grid_domain(const Case& c, Vec3 lo, Vec3 hi) {
  if (c.grid->min) {
    lo = *c.grid->min;
    hi = *c.grid->max;
  } else {
    const Vec3 margin = (kGridMarginFraction * (hi - lo))
                            .cwiseMax(Vec3::Constant(kGridMarginMinCells * c.grid->cell_size));
    lo -= margin;
    hi += margin;
  }
  if (c.solver.geometry == Geometry::Axisymmetric) lo[0] = 0.0;
  return {lo, hi};
}

}  // namespace coldspray::case_file
