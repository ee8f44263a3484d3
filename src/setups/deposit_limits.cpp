#include "setups/deposit_limits.hpp"

#include <fmt/format.h>

#include "case/size_estimate.hpp"
#include "case/size_limits.hpp"
#include "core/error.hpp"
#include "geometry/shape.hpp"
#include "setups/deposit_case.hpp"
#include "studies/deposit_room.hpp"

namespace coldspray::setups {

namespace {

void check_room(const DepositFile& file, const std::vector<double>& diameters) {
  const studies::DepositRoom room = studies::deposit_room(file.plan, diameters);
  if (room.fits()) return;
  throw InputError(
      file.count_where, "particles.count",
      fmt::format("{} particles cannot fit: their spheres grown by half the clearance ({:.4g} um) "
                  "fill {:.4g} um^3, more than the {:.4g} um^3 of the region they lie in (the "
                  "patch and the heights their arrivals over arrival_window give, grown by the "
                  "largest such radius), which holds about {} of them: widen the patch or the "
                  "arrival_window, or spray fewer",
                  file.plan.count, 0.5e6 * file.plan.clearance, room.needed * 1e18,
                  room.room * 1e18, room.most));
}

void check_points(const DepositFile& file, const std::vector<double>& diameters,
                  const std::vector<case_file::Override>& sets) {
  double particles = 0.0;
  for (const double d : diameters)
    particles += case_file::lattice_points(geometry::Sphere{{0, 0, 0}, 0.5 * d}, file.spacing);
  const double substrate = case_file::lattice_points(substrate_box(file), file.spacing);
  // The generated case is an MPM case with no cut at the grid's faces (deposit_case.cpp).
  case_file::Case c;
  c.limits = case_file::limits_of_overrides(sets);
  const case_file::SizeCap cap = case_file::point_cap(c);
  if (particles + substrate <= cap.value) return;
  const bool by_count = particles >= substrate;
  throw InputError(
      by_count ? file.count_where : file.patch_where, by_count ? "particles.count" : "patch",
      fmt::format("the deposit would have about {:.3g} points ({} particles about {:.3g}, the "
                  "substrate under the patch about {:.3g}, at spacing {:.4g} m), more than {}: "
                  "spray fewer, narrow the patch, coarsen the grid or raise limits.max_points "
                  "(--set limits.max_points=N)",
                  particles + substrate, file.plan.count, particles, substrate, file.spacing,
                  cap.source));
}

}  // namespace

void check_deposit_size(const DepositFile& file, const std::vector<case_file::Override>& sets) {
  const std::vector<double> diameters = studies::draw_diameters(file.plan);
  check_room(file, diameters);
  check_points(file, diameters, sets);
}

}  // namespace coldspray::setups
