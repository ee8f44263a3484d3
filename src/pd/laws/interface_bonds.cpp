#include "pd/laws/interface_bonds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "case/located_error.hpp"
#include "pd/laws/bulk_fracture.hpp"

namespace coldspray::pd {

double InterfaceBondLaw::break_stretch() const {
  return yield_stretch + std::log(1.0 / kBreakFraction) / softening;
}

double critical_stretch(double fracture_energy, double bulk_modulus, double delta) {
  return std::sqrt(5.0 * fracture_energy / (9.0 * bulk_modulus * delta));
}

double next_largest_stretch(const InterfaceBondLaw& law, double stretch, double largest) {
  if (stretch < 0.0) return std::max(largest, 0.0);
  if (largest == kUnbonded) return kUnbonded;
  largest = std::max(largest, stretch);
  return largest >= law.break_stretch() ? kUnbonded : largest;
}

double envelope_per_micromodulus(const InterfaceBondLaw& law, double stretch) {
  if (stretch <= law.yield_stretch) return stretch;
  if (stretch >= law.break_stretch()) return 0.0;
  return law.yield_stretch * std::exp(-law.softening * (stretch - law.yield_stretch));  // eq 24
}

double force_per_micromodulus(const InterfaceBondLaw& law, double stretch, double largest) {
  if (stretch < 0.0) return -stretch;  // eq 25
  if (largest == kUnbonded || stretch == 0.0) return 0.0;
  if (stretch >= largest) return -envelope_per_micromodulus(law, stretch);
  // Unloading: along the secant from the largest stretch's force to the origin.
  return -stretch * envelope_per_micromodulus(law, largest) / largest;
}

namespace {

// The bond's law: s_c from the interface's fracture energy (the case's, or gamma_a + gamma_b),
// s_y and m from the bulk-fracture fit, which is in units of s_c, unless the case gives them.
InterfaceBondLaw bond_law(const ContactLawInputs& in) {
  const case_file::PeridynamicsContact& contact = in.c.contact.peridynamics;
  const double gamma_a = in.a.surface_energy;
  const double gamma_b = in.b.surface_energy;
  if (!contact.fracture_energy && (gamma_a <= 0.0 || gamma_b <= 0.0))
    case_file::fail_at(
        in.c, "contact.peridynamics.fracture_energy",
        fmt::format("contact model 2 needs the interface's fracture energy: give "
                    "contact.peridynamics.fracture_energy, or a surface_energy to materials "
                    "'{}' and '{}' (then G_c = gamma_a + gamma_b)",
                    in.a.name, in.b.name));
  const double G_c = contact.fracture_energy.value_or(gamma_a + gamma_b);
  const double s_c = critical_stretch(G_c, in.bulk_modulus, in.horizon);
  const InterfaceBondLaw fit = scaled_law(
      fit_interface_law(bulk_fracture_curve(in.settings.horizon_factor, kBulkFractureSamples)),
      s_c);
  return {contact.yield_stretch.value_or(fit.yield_stretch),
          contact.softening.value_or(fit.softening)};
}

}  // namespace

InterfaceBonds InterfaceBonds::make(const ContactLawInputs& in) {
  InterfaceBonds law;
  law.rest = {in.c.contact.peridynamics.repulsion.distance * in.spacing,
              in.c.contact.peridynamics.repulsion.initial_fraction};
  law.micromodulus = in.micromodulus();
  law.bond = bond_law(in);
  law.reach = law.rest.distance * (1.0 + law.bond.break_stretch());
  return law;
}

}  // namespace coldspray::pd
