// Helpers shared by the case/ tests: paths of the test cases, InputError expectations and a
// field-by-field comparison of materials (material.hpp's structs have no operator==).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "core/error.hpp"
#include "input_error.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file::testing {

inline std::string case_path(const std::string& name) {
  return std::string(COLDSPRAY_TEST_DATA) + "/cases/" + name;
}

// A case of examples/, e.g. "verification/hertz.yaml".
inline std::string example(const std::string& name) {
  return std::string(COLDSPRAY_SOURCE_DIR) + "/examples/" + name;
}

// The InputError expectations all the tests share (tests/support/input_error.hpp).
using coldspray::testing::contains;
using coldspray::testing::input_error;

inline void expect_same(const materials::strength::Elastic&, const materials::strength::Elastic&) {}
inline void expect_same(const materials::strength::VonMises& a,
                        const materials::strength::VonMises& b) {
  EXPECT_EQ(a.yield_stress, b.yield_stress);
  EXPECT_EQ(a.hardening_modulus, b.hardening_modulus);
}
inline void expect_same(const materials::strength::JohnsonCook& a,
                        const materials::strength::JohnsonCook& b) {
  EXPECT_EQ(a.A, b.A);
  EXPECT_EQ(a.B, b.B);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.C, b.C);
  EXPECT_EQ(a.m, b.m);
  EXPECT_EQ(a.reference_strain_rate, b.reference_strain_rate);
  EXPECT_EQ(a.reference_temperature, b.reference_temperature);
}
inline void expect_same(const materials::strength::Ptw& a, const materials::strength::Ptw& b) {
  EXPECT_EQ(a.theta, b.theta);
  EXPECT_EQ(a.p, b.p);
  EXPECT_EQ(a.s0, b.s0);
  EXPECT_EQ(a.s_inf, b.s_inf);
  EXPECT_EQ(a.kappa, b.kappa);
  EXPECT_EQ(a.gamma, b.gamma);
  EXPECT_EQ(a.y0, b.y0);
  EXPECT_EQ(a.y_inf, b.y_inf);
  EXPECT_EQ(a.y1, b.y1);
  EXPECT_EQ(a.y2, b.y2);
  EXPECT_EQ(a.s1, b.s1);
  EXPECT_EQ(a.atomic_mass, b.atomic_mass);
}
inline void expect_same(const materials::shear_modulus::Constant&,
                        const materials::shear_modulus::Constant&) {}
inline void expect_same(const materials::shear_modulus::Mts& a,
                        const materials::shear_modulus::Mts& b) {
  EXPECT_EQ(a.mu0, b.mu0);
  EXPECT_EQ(a.D, b.D);
  EXPECT_EQ(a.T0, b.T0);
}
inline void expect_same(const materials::melt::Constant& a, const materials::melt::Constant& b) {
  EXPECT_EQ(a.temperature, b.temperature);
}
inline void expect_same(const materials::melt::Scg& a, const materials::melt::Scg& b) {
  EXPECT_EQ(a.Tm0, b.Tm0);
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.gamma0, b.gamma0);
}
inline void expect_same(const materials::eos::Linear&, const materials::eos::Linear&) {}
inline void expect_same(const materials::eos::MieGruneisen& a,
                        const materials::eos::MieGruneisen& b) {
  EXPECT_EQ(a.c0, b.c0);
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.gamma0, b.gamma0);
}

template <class... Ts>
void expect_same(const std::variant<Ts...>& a, const std::variant<Ts...>& b) {
  ASSERT_EQ(a.index(), b.index());
  std::visit([&](const auto& x) { expect_same(x, std::get<std::decay_t<decltype(x)>>(b)); }, a);
}

inline void expect_same(const materials::Material& a, const materials::Material& b) {
  SCOPED_TRACE("material " + a.name);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.elastic.shear_modulus, b.elastic.shear_modulus);
  EXPECT_EQ(a.elastic.bulk_modulus, b.elastic.bulk_modulus);
  expect_same(a.strength, b.strength);
  expect_same(a.shear_modulus, b.shear_modulus);
  expect_same(a.melt, b.melt);
  expect_same(a.eos, b.eos);
  EXPECT_EQ(a.thermal.specific_heat, b.thermal.specific_heat);
  EXPECT_EQ(a.thermal.taylor_quinney, b.thermal.taylor_quinney);
  EXPECT_EQ(a.sources, b.sources);
}

}  // namespace coldspray::case_file::testing
