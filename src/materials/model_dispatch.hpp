// Resolving a Material's four model variants (strength, shear modulus, melt, EOS) once, so that
// loops over many points run code instantiated for the concrete models: no variant switch and no
// virtual call per point. visit_models calls F with a ModelSet<S, G, M, E> of the concrete
// parameter structs; everything in it inlines.
//
// Pattern for a solver's hot loop (one dispatch per material and pass, not per point):
//
//   visit_models(material, [&](const auto& models) {
//     for (std::size_t i = begin; i < end; ++i)
//       update_point(models, kinematics[i], options, states[i]);  // stress_update_kernel.hpp
//   });
//
// or for_each_point below, which is exactly that loop.
#pragma once

#include <cstddef>
#include <type_traits>
#include <variant>

#include "materials/eos/linear.hpp"
#include "materials/eos/mie_gruneisen.hpp"
#include "materials/material.hpp"
#include "materials/melt/constant.hpp"
#include "materials/melt/scg.hpp"
#include "materials/shear_modulus/constant.hpp"
#include "materials/shear_modulus/mts.hpp"
#include "materials/strength/conditions.hpp"
#include "materials/strength/elastic.hpp"
#include "materials/strength/johnson_cook.hpp"
#include "materials/strength/prepare.hpp"
#include "materials/strength/ptw.hpp"
#include "materials/strength/von_mises.hpp"

namespace coldspray::materials {

// A material with its sub-models resolved to concrete types. Holds references: it lives only
// for the duration of a visit_models call.
template <class Strength, class Shear, class Melt, class Eos>
struct ModelSet {
  const Material& material;
  const Strength& strength_model;
  const Shear& shear_model;
  const Melt& melt_model;
  const Eos& eos_model;

  double shear_modulus_at(double temperature) const {
    return shear_modulus::modulus(shear_model, material.elastic, temperature);
  }
  double melt_temperature_at(double density) const {
    return melt::temperature(melt_model, density / material.density);
  }
  double flow_stress_at(double eqps, double rate, const strength::Conditions& c) const {
    return strength::flow_stress(strength_model, eqps, rate, c);
  }
  // The flow stress as a function of (eqps, rate) under fixed conditions (strength/prepare.hpp).
  auto flow_stress_in_step(const strength::Conditions& c) const {
    return strength::prepare(strength_model, c);
  }
  // p = A(J) + B E (thesis eq 3.42), E per reference volume.
  double reference_pressure(double J) const {
    return eos::reference_pressure(eos_model, material, J);
  }
  double energy_coefficient() const { return eos::energy_coefficient(eos_model); }
  double tangent_bulk_modulus(double J, double energy) const {
    return eos::tangent_bulk_modulus(eos_model, material, J, energy);
  }
};

// Calls f(ModelSet<...>) for m's concrete models and returns what f returns.
template <class F>
decltype(auto) visit_models(const Material& m, F&& f) {
  return std::visit(
      [&m, &f](const auto& s, const auto& g, const auto& t, const auto& e) -> decltype(auto) {
        using Set = ModelSet<std::decay_t<decltype(s)>, std::decay_t<decltype(g)>,
                             std::decay_t<decltype(t)>, std::decay_t<decltype(e)>>;
        return f(Set{m, s, g, t, e});
      },
      m.strength, m.shear_modulus, m.melt, m.eos);
}

// kernel(models, i) for i in [0, n), the models resolved once outside the loop.
template <class Kernel>
void for_each_point(const Material& m, std::size_t n, Kernel&& kernel) {
  visit_models(m, [n, &kernel](const auto& models) {
    for (std::size_t i = 0; i < n; ++i) kernel(models, i);
  });
}

}  // namespace coldspray::materials
