// visit_models resolves each variant to its concrete model once; for_each_point runs a kernel
// instantiated for those models over many points.
#include "materials/model_dispatch.hpp"

#include <gtest/gtest.h>

#include <type_traits>
#include <vector>

#include "materials/stress_update_kernel.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

template <class S, class G, class M, class E>
bool resolves_to(const Material& m) {
  return visit_models(m, [](const auto& models) {
    using Set = std::decay_t<decltype(models)>;
    return std::is_same_v<Set, ModelSet<S, G, M, E>>;
  });
}

TEST(MaterialsDispatch, ResolvesConcreteModelTypes) {
  EXPECT_TRUE((resolves_to<strength::Ptw, shear_modulus::Mts, melt::Scg, eos::MieGruneisen>(
      testing::al_ptw())));
  EXPECT_TRUE((resolves_to<strength::JohnsonCook, shear_modulus::Constant, melt::Constant,
                           eos::MieGruneisen>(testing::cu_jc())));
  EXPECT_TRUE(
      (resolves_to<strength::VonMises, shear_modulus::Constant, melt::Constant, eos::Linear>(
          testing::linear_hardening())));
  EXPECT_TRUE(
      (resolves_to<strength::Elastic, shear_modulus::Constant, melt::Scg, eos::MieGruneisen>(
          testing::al_elastic())));
  EXPECT_FALSE(
      (resolves_to<strength::JohnsonCook, shear_modulus::Mts, melt::Scg, eos::MieGruneisen>(
          testing::al_ptw())));
}

// The resolved models refer to the material's own parameters (no copies).
TEST(MaterialsDispatch, ModelSetReferencesTheMaterial) {
  const Material m = testing::al_ptw();
  const bool same = visit_models(m, [&](const auto& models) {
    return static_cast<const void*>(&models.strength_model) ==
               static_cast<const void*>(&std::get<strength::Ptw>(m.strength)) &&
           &models.material == &m;
  });
  EXPECT_TRUE(same);
}

// An array loop through for_each_point gives bit-identical results to the single-point API.
TEST(MaterialsDispatch, ArrayLoopMatchesSinglePointUpdates) {
  const Material m = testing::al_ptw();
  const std::size_t n = 64;
  std::vector<PointState> loop(n, initial_state(m, 298.0)), single = loop;
  std::vector<StepKinematics> k(n);
  for (std::size_t i = 0; i < n; ++i) {
    k[i].strain_increment(0, 1) = k[i].strain_increment(1, 0) = 1e-4 * (i + 1);
    k[i].strain_increment(2, 2) = -2e-5 * i;
    k[i].dt = 1e-9;
    k[i].J_new = 1.0 - 2e-5 * i;
  }
  const UpdateOptions opt;
  for_each_point(
      m, n, [&](const auto& models, std::size_t i) { update_point(models, k[i], opt, loop[i]); });
  for (std::size_t i = 0; i < n; ++i) update_stress(m, k[i], opt, single[i]);
  int plastic = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(loop[i].stress.matrix(), single[i].stress.matrix()) << i;
    EXPECT_EQ(loop[i].eqps, single[i].eqps) << i;
    EXPECT_EQ(loop[i].temperature, single[i].temperature) << i;
    EXPECT_EQ(loop[i].energy, single[i].energy) << i;
    plastic += loop[i].eqps > 0.0;
  }
  EXPECT_GT(plastic, 10);
}

}  // namespace
}  // namespace coldspray::materials
