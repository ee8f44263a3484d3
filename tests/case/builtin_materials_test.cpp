#include <gtest/gtest.h>

#include <sstream>

#include "case/case_materials.hpp"
#include "case/document.hpp"
#include "case/load.hpp"
#include "case/material_schema.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::input_error;
namespace strength = materials::strength;

TEST(BuiltinMaterials, AreTheFourDataFiles) {
  EXPECT_EQ(builtin_material_names(),
            (std::vector<std::string>{"al-jc", "al-ptw", "cu-jc", "cu-ptw"}));
}

TEST(BuiltinMaterials, AllLoadWithASourceForEveryGroup) {
  for (const std::string& name : builtin_material_names()) {
    SCOPED_TRACE(name);
    const materials::Material m = builtin_material(name);
    EXPECT_EQ(m.name, name);
    EXPECT_FALSE(m.description.empty());
    for (std::string_view group : kMaterialGroups) {
      ASSERT_TRUE(m.sources.contains(std::string(group))) << group;
      EXPECT_NE(m.sources.at(std::string(group)), "default");
    }
  }
}

// Values against data/materials/al-ptw.yaml.
TEST(BuiltinMaterials, AlPtwHasItsDataFileValues) {
  const materials::Material m = builtin_material("al-ptw");
  EXPECT_EQ(m.density, 2700.0);
  EXPECT_EQ(m.elastic.shear_modulus, 26.0e9);
  EXPECT_EQ(m.elastic.bulk_modulus, 66.4e9);
  const auto& ptw = std::get<strength::Ptw>(m.strength);
  EXPECT_EQ(ptw.theta, 0.01156);
  EXPECT_EQ(ptw.p, 3.0);
  EXPECT_EQ(ptw.s0, 0.01489);
  EXPECT_EQ(ptw.s_inf, 0.002819);
  EXPECT_EQ(ptw.kappa, 1.3);
  EXPECT_EQ(ptw.gamma, 2.04e-5);
  EXPECT_EQ(ptw.y0, 0.0115);
  EXPECT_EQ(ptw.y_inf, 0.002003);
  EXPECT_EQ(ptw.y1, 0.0168);
  EXPECT_EQ(ptw.y2, 0.2339);
  EXPECT_EQ(ptw.s1, 0.2034);
  EXPECT_EQ(ptw.atomic_mass, 4.48039e-26);
  const auto& mts = std::get<materials::shear_modulus::Mts>(m.shear_modulus);
  EXPECT_EQ(mts.mu0, 28.8e9);
  EXPECT_EQ(mts.D, 3.44e9);
  EXPECT_EQ(mts.T0, 215.0);
  const auto& scg = std::get<materials::melt::Scg>(m.melt);
  EXPECT_EQ(scg.Tm0, 1220.0);
  EXPECT_EQ(scg.a, 1.5);
  EXPECT_EQ(scg.gamma0, 1.97);
  const auto& eos = std::get<materials::eos::MieGruneisen>(m.eos);
  EXPECT_EQ(eos.c0, 5386.0);
  EXPECT_EQ(eos.s, 1.339);
  EXPECT_EQ(eos.gamma0, 1.97);
  EXPECT_EQ(m.thermal.specific_heat, 896.0);
  EXPECT_EQ(m.thermal.taylor_quinney, 0.9);
  EXPECT_EQ(m.sources.at("strength"),
            "thesis Table 2.1 (PTW parameters for Al, from Rahmati & Jodoin); the table's atomic "
            "mass 4.48039e-23 \"kg\" is the mass of an Al atom in grams, the physical 26.9815 u = "
            "4.48039e-26 kg is used");
}

// Values against data/materials/al-jc.yaml.
TEST(BuiltinMaterials, AlJcHasItsDataFileValues) {
  const materials::Material m = builtin_material("al-jc");
  const auto& jc = std::get<strength::JohnsonCook>(m.strength);
  EXPECT_EQ(jc.A, 148.4e6);
  EXPECT_EQ(jc.B, 345.5e6);
  EXPECT_EQ(jc.n, 0.183);
  EXPECT_EQ(jc.C, 0.001);
  EXPECT_EQ(jc.m, 0.895);
  EXPECT_EQ(jc.reference_strain_rate, 1.0);
  EXPECT_EQ(jc.reference_temperature, 298.0);
  EXPECT_TRUE(std::holds_alternative<materials::shear_modulus::Constant>(m.shear_modulus));
  EXPECT_EQ(std::get<materials::melt::Constant>(m.melt).temperature, 916.0);
}

// Values against data/materials/cu-jc.yaml and cu-ptw.yaml.
TEST(BuiltinMaterials, CopperHasItsDataFileValues) {
  const materials::Material jc_cu = builtin_material("cu-jc");
  EXPECT_EQ(jc_cu.density, 8930.0);
  EXPECT_EQ(jc_cu.elastic.bulk_modulus, 129.0e9);
  const auto& jc = std::get<strength::JohnsonCook>(jc_cu.strength);
  EXPECT_EQ(jc.A, 90e6);
  EXPECT_EQ(jc.B, 292e6);
  EXPECT_EQ(jc.n, 0.31);
  EXPECT_EQ(jc.C, 0.025);
  EXPECT_EQ(jc.m, 1.09);
  EXPECT_EQ(std::get<materials::melt::Constant>(jc_cu.melt).temperature, 1356.0);
  EXPECT_EQ(std::get<materials::eos::MieGruneisen>(jc_cu.eos).c0, 3940.0);
  EXPECT_EQ(jc_cu.thermal.specific_heat, 383.0);

  const materials::Material ptw_cu = builtin_material("cu-ptw");
  const auto& ptw = std::get<strength::Ptw>(ptw_cu.strength);
  EXPECT_EQ(ptw.y0, 1.0e-4);
  EXPECT_EQ(ptw.s1, 0.25);
  EXPECT_EQ(ptw.atomic_mass, 1.05521e-25);
  EXPECT_EQ(std::get<materials::shear_modulus::Mts>(ptw_cu.shear_modulus).mu0, 47.7e9);
  EXPECT_EQ(std::get<materials::melt::Scg>(ptw_cu.melt).Tm0, 1790.0);
}

TEST(BuiltinMaterials, UnknownNameSuggestsTheClosest) {
  const InputError e = input_error([] { builtin_material("al-ptv"); });
  EXPECT_TRUE(contains(e.message(), "unknown built-in material 'al-ptv'; did you mean 'al-ptw'?"));
}

TEST(BuiltinMaterials, ErrorsInADataFileNameTheBuiltin) {
  const Document doc = Document::from_text("builtin:broken", "density: -1 kg/m^3\n");
  const InputError e = input_error([&] { read_material(doc, doc.root(), "", "broken"); });
  EXPECT_EQ(e.where(), "builtin:broken:1:10");
  EXPECT_EQ(e.key(), "density");
}

TEST(ResolveMaterial, FindsBuiltinsAndCaseMaterials) {
  testing::expect_same(resolve_material("cu-jc"), builtin_material("cu-jc"));
  const std::string file = case_path("materials-only.yaml");
  const materials::Material hard = resolve_material(file + ":hard-al");
  EXPECT_EQ(hard.name, "hard-al");
  EXPECT_EQ(std::get<strength::Ptw>(hard.strength).y0, 0.013);
  const materials::Material soft = resolve_material(file + ":soft-al");
  EXPECT_EQ(std::get<strength::VonMises>(soft.strength).yield_stress, 50e6);
  EXPECT_TRUE(std::holds_alternative<materials::eos::Linear>(soft.eos));
  // A case may use a built-in it does not define.
  testing::expect_same(resolve_material(file + ":al-jc"), builtin_material("al-jc"));
}

TEST(ResolveMaterial, ReportsUnknownNamesAndFiles) {
  const std::string file = case_path("materials-only.yaml");
  const InputError e = input_error([&] { resolve_material(file + ":hard-alu"); });
  EXPECT_EQ(e.where(), file);
  EXPECT_EQ(e.key(), "materials.hard-alu");
  EXPECT_TRUE(contains(e.message(), "did you mean 'hard-al'?"));
  EXPECT_EQ(input_error([] { resolve_material("no-such-file.yaml:x"); }).where(),
            "no-such-file.yaml");
}

TEST(PrintMaterial, ListsEveryParameterWithItsUnitAndEachGroupsSource) {
  std::ostringstream out;
  print_material(builtin_material("al-ptw"), out);
  const std::string text = out.str();
  for (const char* part :
       {"material al-ptw", "density                    2700 kg/m^3",
        "  shear_modulus            2.6e+10 Pa", "strength                   model: ptw",
        "  y0                       0.0115\n", "  atomic_mass              4.48039e-26 kg",
        "  mu0                      2.88e+10 Pa", "  T0                       215 K",
        "  c0                       5386 m/s", "specific_heat              896 J/kg/K",
        "  source: thesis Table 2.1 (PTW parameters for Al, from Rahmati & Jodoin)",
        "  source: thesis §3.5.3 (chi = 0.9)"}) {
    EXPECT_TRUE(contains(text, part));
  }
}

}  // namespace
}  // namespace coldspray::case_file
