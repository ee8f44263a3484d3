#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;

TEST(LoadCase, FillsEveryDefault) {
  const Case c = load_case(case_path("minimal.yaml"));
  EXPECT_EQ(c.name, "minimal");
  EXPECT_EQ(c.description, "");
  EXPECT_EQ(c.source_file, case_path("minimal.yaml"));
  ASSERT_EQ(c.bodies.size(), 1u);
  const Body& b = c.bodies[0];
  EXPECT_EQ(b.velocity, Vec3::Zero());
  EXPECT_EQ(b.temperature, 298.0);
  EXPECT_TRUE(b.absorbing.empty());
  EXPECT_TRUE(b.fixed.empty());
  EXPECT_FALSE(c.grid->min.has_value());
  EXPECT_FALSE(c.grid->max.has_value());
  ASSERT_EQ(c.grid->faces.size(), 6u);
  for (const auto& [face, condition] : c.grid->faces) EXPECT_EQ(condition, FaceCondition::Free);
  EXPECT_EQ(c.solver.method, Method::Mpm);
  EXPECT_EQ(c.solver.geometry, Geometry::ThreeD);
  EXPECT_EQ(c.solver.shape_function, ShapeFunction::Gimp);
  EXPECT_EQ(c.solver.cfl, 0.3);
  EXPECT_FALSE(c.solver.dt_scale.has_value());
  EXPECT_TRUE(c.solver.artificial_viscosity.enabled);
  EXPECT_EQ(c.solver.artificial_viscosity.linear, 0.06);
  EXPECT_EQ(c.solver.artificial_viscosity.quadratic, 1.5);
  EXPECT_EQ(c.contact.mpm.normal, ContactNormal::MaxGradient);
  EXPECT_EQ(c.contact.mpm.friction, 0.0);
  EXPECT_EQ(c.output.history_interval, 0.0);
  EXPECT_EQ(c.output.snapshot_interval, 0.0);
  EXPECT_TRUE(c.output.probes.empty());
}

TEST(LoadCase, ReadsEveryKeyInSi) {
  const Case c = load_case(case_path("full.yaml"));
  EXPECT_EQ(c.name, "full-case");
  EXPECT_EQ(c.description, "Every key of the case file: the round-trip test case");
  ASSERT_EQ(c.bodies.size(), 4u);

  const Body& particle = c.bodies[0];
  EXPECT_EQ(particle.name, "particle");
  EXPECT_EQ(particle.material, "soft-al");
  const auto& sphere = std::get<geometry::Sphere>(particle.shape);
  EXPECT_EQ(sphere.center, Vec3(0, 0, 7e-6));
  EXPECT_EQ(sphere.radius, 7e-6);
  EXPECT_EQ(particle.spacing, 0.175e-6);
  EXPECT_EQ(particle.velocity, Vec3(0, 0, -810));
  EXPECT_EQ(particle.temperature, 350.0);

  const Body& substrate = c.bodies[1];
  const auto& cylinder = std::get<geometry::Cylinder>(substrate.shape);
  EXPECT_EQ(cylinder.base_center, Vec3(0, 0, -10e-6));
  EXPECT_EQ(cylinder.radius, 15e-6);
  EXPECT_EQ(cylinder.height, 10e-6);
  EXPECT_EQ(substrate.absorbing, (std::vector<BodyFace>{BodyFace::Bottom, BodyFace::Side}));
  EXPECT_EQ(substrate.fixed, std::vector<BodyFace>{BodyFace::Bottom});

  const auto& box = std::get<geometry::Box>(c.bodies[2].shape);
  EXPECT_EQ(box.min, Vec3(-20e-6, -20e-6, -30e-6));
  EXPECT_EQ(box.max, Vec3(20e-6, 20e-6, -20e-6));
  EXPECT_EQ(c.bodies[3].velocity, Vec3(1, -2, 3));  // mixed units and a bare SI number

  EXPECT_EQ(c.grid->cell_size, 0.7e-6);
  EXPECT_EQ(c.grid->min, Vec3(-40e-6, -40e-6, -40e-6));
  EXPECT_EQ(c.grid->max, Vec3(40e-6, 40e-6, 30e-6));
  EXPECT_EQ(c.grid->faces.at(GridFace::XMin), FaceCondition::Fixed);
  EXPECT_EQ(c.grid->faces.at(GridFace::ZMin), FaceCondition::Roller);
  EXPECT_EQ(c.grid->faces.at(GridFace::ZMax), FaceCondition::Free);

  EXPECT_EQ(c.solver.shape_function, ShapeFunction::Linear);
  EXPECT_EQ(c.solver.end_time, 80e-9);
  EXPECT_EQ(c.solver.cfl, 0.25);
  EXPECT_EQ(c.solver.dt_scale, 0.2);
  EXPECT_FALSE(c.solver.artificial_viscosity.enabled);
  EXPECT_EQ(c.solver.artificial_viscosity.linear, 0.1);
  EXPECT_EQ(c.solver.artificial_viscosity.quadratic, 2.0);

  EXPECT_EQ(c.contact.mpm.normal, ContactNormal::Body);
  EXPECT_EQ(c.contact.mpm.normal_body, "substrate");
  EXPECT_EQ(c.contact.mpm.friction, 0.1);

  EXPECT_EQ(c.output.history_interval, 1e-9);
  EXPECT_EQ(c.output.snapshot_interval, 10e-9);
  ASSERT_EQ(c.output.probes.size(), 2u);
  EXPECT_EQ(c.output.probes[0].name, "p1");
  EXPECT_EQ(c.output.probes[0].position, Vec3(0, 0, -1e-6));
  EXPECT_EQ(c.output.probes[0].fields, (std::vector<std::string>{"pressure", "velocity_z"}));
  EXPECT_EQ(c.output.probes[1].position, Vec3(5e-6, 0, -2e-6));
}

TEST(LoadCase, KeepsTheMaterialsTheBodiesUseKeyedByTheirNames) {
  const Case c = load_case(case_path("full.yaml"));
  ASSERT_EQ(c.materials.size(), 4u);  // 'unused' is dropped, the built-in al-jc is added
  for (const char* name : {"soft-al", "steel-vm", "cu-vm", "al-jc"}) {
    ASSERT_TRUE(c.materials.contains(name)) << name;
    EXPECT_EQ(c.materials.at(name).name, name);
  }
  testing::expect_same(c.materials.at("al-jc"), builtin_material("al-jc"));
}

TEST(LoadCase, ConvertsYoungsModulusAndPoissonRatio) {
  const materials::Material steel = load_case(case_path("full.yaml")).materials.at("steel-vm");
  // E = 200 GPa, nu = 0.3: G = E / (2 (1 + nu)) = 76.923 GPa, K = E / (3 (1 - 2 nu)) = 166.67 GPa.
  EXPECT_DOUBLE_EQ(steel.elastic.shear_modulus, 200e9 / 2.6);
  EXPECT_DOUBLE_EQ(steel.elastic.bulk_modulus, 200e9 / 1.2);
  EXPECT_NEAR(steel.elastic.shear_modulus, 76.923e9, 1e6);
  EXPECT_NEAR(steel.elastic.bulk_modulus, 166.667e9, 1e6);
  EXPECT_EQ(steel.thermal.taylor_quinney, 0.85);
  const auto& vm = std::get<materials::strength::VonMises>(steel.strength);
  EXPECT_EQ(vm.yield_stress, 350e6);
  EXPECT_EQ(vm.hardening_modulus, 1e9);
  EXPECT_TRUE(std::holds_alternative<materials::shear_modulus::Constant>(steel.shear_modulus));
  EXPECT_TRUE(std::holds_alternative<materials::eos::Linear>(steel.eos));
  EXPECT_EQ(std::get<materials::melt::Constant>(steel.melt).temperature, 1800.0);
}

TEST(LoadCase, MergesAMaterialOverItsBase) {
  const Case c = load_case(case_path("full.yaml"));
  const materials::Material base = builtin_material("al-ptw");
  const materials::Material& soft = c.materials.at("soft-al");
  EXPECT_EQ(soft.density, 2710.0);
  const auto& ptw = std::get<materials::strength::Ptw>(soft.strength);
  const auto& base_ptw = std::get<materials::strength::Ptw>(base.strength);
  EXPECT_EQ(ptw.y0, 0.012);        // overridden
  EXPECT_EQ(ptw.s0, base_ptw.s0);  // kept from the base, same model
  EXPECT_EQ(ptw.theta, base_ptw.theta);
  EXPECT_EQ(soft.elastic.shear_modulus, base.elastic.shear_modulus);
  testing::expect_same(soft.shear_modulus, base.shear_modulus);
  testing::expect_same(soft.melt, base.melt);
  testing::expect_same(soft.eos, base.eos);
  EXPECT_EQ(soft.description, base.description);
}

TEST(LoadCase, ReplacesAGroupWhoseModelChanges) {
  const materials::Material cu = load_case(case_path("full.yaml")).materials.at("cu-vm");
  const auto& vm = std::get<materials::strength::VonMises>(cu.strength);
  EXPECT_EQ(vm.yield_stress, 200e6);
  EXPECT_EQ(vm.hardening_modulus, 0.0);  // the default, nothing from the base's Johnson-Cook
  EXPECT_TRUE(std::holds_alternative<materials::eos::Linear>(cu.eos));
  EXPECT_EQ(cu.density, builtin_material("cu-jc").density);
}

TEST(LoadCase, AttributesSourcesOfGroupsACaseSets) {
  const Case c = load_case(case_path("full.yaml"));
  const materials::Material base = builtin_material("al-ptw");
  const auto& sources = c.materials.at("soft-al").sources;
  EXPECT_EQ(sources.at("density"), "a test value");  // given in the case
  EXPECT_EQ(sources.at("strength"), case_path("full.yaml") + ", material 'soft-al', over al-ptw: " +
                                        base.sources.at("strength"));
  EXPECT_EQ(sources.at("eos"), base.sources.at("eos"));  // untouched: the base's source
  const auto& cu = c.materials.at("cu-vm").sources;  // another model: nothing of the base's kept
  EXPECT_EQ(cu.at("eos"), case_path("full.yaml") + ", material 'cu-vm'");
  EXPECT_EQ(cu.at("melt"), builtin_material("cu-jc").sources.at("melt"));
  const auto& steel = c.materials.at("steel-vm").sources;
  EXPECT_EQ(steel.at("elastic"), case_path("full.yaml") + ", material 'steel-vm'");
  EXPECT_EQ(steel.at("eos"), "default");
}

TEST(LoadCase, AcceptsAnAxisymmetricCaseOnTheAxis) {
  const Case c = load_case(case_path("axisymmetric.yaml"));
  EXPECT_EQ(c.solver.geometry, Geometry::Axisymmetric);
}

// A generated case (coldspray impact): read like a file, with errors at the value's origin.
constexpr const char* kGenerated = R"(name: generated
bodies:
  - name: particle
    material: al-ptw
    shape: {type: sphere, center: [0, 0, 7 um], radius: 7 um}
    spacing: 0.175 um
grid:
  cell_size: 0.7 um
solver:
  end_time: 80 ns
)";

TEST(LoadCaseText, ReadsLikeAFile) {
  const Case c = load_case_text("generator", kGenerated);
  EXPECT_EQ(c.name, "generated");
  EXPECT_EQ(c.source_file, "generator");
  EXPECT_EQ(c.bodies.at(0).spacing, 0.175e-6);
  EXPECT_EQ(c.solver.cfl, 0.3);
}

TEST(LoadCaseText, ReportsAValueAtItsOrigin) {
  const std::vector<ValueOrigin> origins = {{"bodies.particle.material", "--material"},
                                            {"solver.end_time", "--end-time"}};
  std::string text = kGenerated;
  text.replace(text.find("al-ptw"), 6, "al-ptq");
  const InputError e = testing::input_error([&] { load_case_text("generator", text, origins); });
  EXPECT_EQ(e.where(), "--material");
  EXPECT_EQ(e.key(), "bodies.particle.material");
  // Without an origin a value is located in the text under the given name.
  const InputError unmarked = testing::input_error([&] { load_case_text("generator", text); });
  EXPECT_EQ(unmarked.where(), "generator:4:15");
}

TEST(LoadCaseText, OverridesWinAndNameThemselves) {
  const std::vector<ValueOrigin> origins = {{"solver.end_time", "--end-time"}};
  const InputError e = testing::input_error([&] {
    load_case_text("generator", kGenerated, origins, {parse_override("solver.end_time=-1 ns")});
  });
  EXPECT_EQ(e.where(), "--set solver.end_time");
  EXPECT_EQ(
      load_case_text("generator", kGenerated, origins, {parse_override("solver.end_time=5 ns")})
          .solver.end_time,
      5e-9);
}

TEST(LoadCaseText, ApplyOverridesEmitsTheEditedTree) {
  const std::string text =
      apply_overrides("generator", kGenerated, {parse_override("solver.cfl=0.2")});
  EXPECT_EQ(load_case_text("re-read", text).solver.cfl, 0.2);
}

}  // namespace
}  // namespace coldspray::case_file

namespace coldspray::case_file {
namespace {

// Three blocks side by side; `extra` is added to the case.
std::string three_bodies(const std::string& extra) {
  std::string text = "name: three\nbodies:\n";
  for (const char* name : {"a", "b", "c"})
    text += std::string("  - {name: ") + name +
            ", material: al-ptw, shape: {type: sphere, center: [0, 0, " +
            (name[0] == 'a'   ? "0"
             : name[0] == 'b' ? "10 um"
                              : "20 um") +
            "], radius: 4 um}, spacing: 1 um}\n";
  return text + "grid: {cell_size: 2 um}\nsolver: {end_time: 1 ns}\n" + extra;
}

// The contact normal's default: MVG for two bodies (FillsEveryDefault, one body), the
// order-independent average gradient for three or more; a given rule is kept.
TEST(LoadCase, ThreeBodiesDefaultToTheAverageGradientNormal) {
  EXPECT_EQ(load_case_text("three", three_bodies("")).contact.mpm.normal,
            ContactNormal::AverageGradient);
  EXPECT_EQ(load_case_text("three", three_bodies("contact: {friction: 0.1}\n")).contact.mpm.normal,
            ContactNormal::AverageGradient);
  EXPECT_EQ(
      load_case_text("three", three_bodies("contact: {normal: highest-id}\n")).contact.mpm.normal,
      ContactNormal::HighestId);
  EXPECT_EQ(load_case_text("generated", kGenerated).contact.mpm.normal, ContactNormal::MaxGradient);
}

}  // namespace
}  // namespace coldspray::case_file
