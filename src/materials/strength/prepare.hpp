// A strength model bound to one step's conditions: f(eqps, rate) for the consistent return.
// Models with terms that depend on the conditions alone evaluate them once (PTW: PtwStep);
// the others simply carry the conditions.
#pragma once

#include "materials/strength/conditions.hpp"
#include "materials/strength/elastic.hpp"
#include "materials/strength/johnson_cook.hpp"
#include "materials/strength/ptw.hpp"
#include "materials/strength/von_mises.hpp"

namespace coldspray::materials::strength {

template <class Model>
class StepFlowStress {
 public:
  StepFlowStress(const Model& m, const Conditions& c) : model_(m), conditions_(c) {}
  double operator()(double eqps, double rate) const {
    return flow_stress(model_, eqps, rate, conditions_);
  }

 private:
  const Model& model_;
  Conditions conditions_;
};

template <class Model>
StepFlowStress<Model> prepare(const Model& m, const Conditions& c) {
  return StepFlowStress<Model>(m, c);
}

}  // namespace coldspray::materials::strength
