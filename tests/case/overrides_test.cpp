#include <gtest/gtest.h>

#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::input_error;

TEST(ParseOverride, SplitsAtTheFirstEqualsSign) {
  const Override o = parse_override("bodies.particle.velocity=[0, 0, -700 m/s]");
  EXPECT_EQ(o.key, "bodies.particle.velocity");
  EXPECT_EQ(o.value, "[0, 0, -700 m/s]");
  const Override spaced = parse_override(" description = a=b ");
  EXPECT_EQ(spaced.key, "description");
  EXPECT_EQ(spaced.value, "a=b");
}

TEST(ParseOverride, RejectsTextWithoutKeyOrValue) {
  EXPECT_EQ(input_error([] { parse_override("solver.cfl"); }).where(), "--set");
  EXPECT_EQ(input_error([] { parse_override("=0.2"); }).where(), "--set");
  const InputError no_value = input_error([] { parse_override("solver.cfl="); });
  EXPECT_EQ(no_value.where(), "--set solver.cfl");
  EXPECT_TRUE(contains(no_value.message(), "no VALUE"));
}

TEST(Overrides, SelectListItemsByName) {
  const Case c = load_case(case_path("axisymmetric.yaml"),
                           {parse_override("bodies.particle.velocity=[0, 0, -700 m/s]")});
  EXPECT_EQ(c.bodies[0].velocity, Vec3(0, 0, -700));
  EXPECT_EQ(c.bodies[1].velocity, Vec3::Zero());
}

TEST(Overrides, SelectListItemsByIndex) {
  const Case c = load_case(case_path("full.yaml"), {parse_override("bodies.1.spacing=0.1 um"),
                                                    parse_override("bodies.1.absorbing.1=top")});
  EXPECT_EQ(c.bodies[1].spacing, 0.1e-6);
  EXPECT_EQ(c.bodies[0].spacing, 0.175e-6);
  EXPECT_EQ(c.bodies[1].absorbing, (std::vector<BodyFace>{BodyFace::Bottom, BodyFace::Top}));
}

TEST(Overrides, CreateMissingKeys) {
  const Case c =
      load_case(case_path("minimal.yaml"),
                {parse_override("solver.cfl=0.2"), parse_override("output.snapshot_interval=5 ns"),
                 parse_override("solver.artificial_viscosity.linear=0.1")});
  EXPECT_EQ(c.solver.cfl, 0.2);
  EXPECT_EQ(c.output.snapshot_interval, 5e-9);
  EXPECT_EQ(c.solver.artificial_viscosity.linear, 0.1);
  EXPECT_EQ(c.solver.artificial_viscosity.quadratic, 1.5);
}

TEST(Overrides, ReplaceValuesAndLaterOnesWin) {
  const Case c = load_case(case_path("full.yaml"),
                           {parse_override("solver.cfl=0.5"), parse_override("solver.cfl=0.4"),
                            parse_override("bodies.substrate.absorbing=[top]"),
                            parse_override("materials.soft-al.strength.y0=0.011")});
  EXPECT_EQ(c.solver.cfl, 0.4);
  EXPECT_EQ(c.bodies[1].absorbing, std::vector<BodyFace>{BodyFace::Top});
  EXPECT_EQ(std::get<materials::strength::Ptw>(c.materials.at("soft-al").strength).y0, 0.011);
}

TEST(Overrides, ErrorsInAnOverriddenValueNameTheOverride) {
  const InputError e =
      input_error([] { load_case(case_path("minimal.yaml"), {parse_override("solver.cfl=2")}); });
  EXPECT_EQ(e.where(), "--set solver.cfl");
  EXPECT_EQ(e.key(), "solver.cfl");
  EXPECT_TRUE(contains(e.message(), "must be in (0, 1]"));

  const InputError inside = input_error([] {
    load_case(case_path("minimal.yaml"),
              {parse_override("bodies.particle.velocity=[0, 0, -700 um]")});
  });
  EXPECT_EQ(inside.where(), "--set bodies.particle.velocity");
  EXPECT_EQ(inside.key(), "bodies.particle.velocity");

  const InputError missing = input_error(
      [] { load_case(case_path("minimal.yaml"), {parse_override("output.probes=[{name: p1}]")}); });
  EXPECT_EQ(missing.where(), "--set output.probes");
  EXPECT_EQ(missing.key(), "output.probes.p1.position");
}

TEST(Overrides, ErrorsElsewhereKeepTheirFilePosition) {
  const InputError e = input_error(
      [] { load_case(case_path("unknown-key.yaml"), {parse_override("solver.cfl=0.2")}); });
  EXPECT_EQ(e.where(), case_path("unknown-key.yaml") + ":7:5");
}

TEST(Overrides, UnknownListItemNamesThePath) {
  const InputError e = input_error([] {
    load_case(case_path("axisymmetric.yaml"), {parse_override("bodies.projectile.spacing=1 um")});
  });
  EXPECT_EQ(e.where(), "--set bodies.projectile.spacing");
  EXPECT_EQ(e.key(), "bodies.projectile");
  EXPECT_TRUE(contains(e.message(), "no item 'projectile' in the list 'bodies'"));
  EXPECT_TRUE(contains(e.message(), "items: particle, substrate"));

  const InputError index = input_error(
      [] { load_case(case_path("axisymmetric.yaml"), {parse_override("bodies.2.spacing=1 um")}); });
  EXPECT_EQ(index.key(), "bodies.2");
}

TEST(Overrides, RejectPathsThroughValuesAndBadYaml) {
  const InputError through =
      input_error([] { load_case(case_path("minimal.yaml"), {parse_override("name.first=x")}); });
  EXPECT_EQ(through.where(), "--set name.first");
  EXPECT_TRUE(contains(through.message(), "'name' is a single value"));

  const InputError yaml = input_error([] {
    load_case(case_path("minimal.yaml"), {parse_override("bodies.particle.velocity=[0, 0")});
  });
  EXPECT_EQ(yaml.where(), "--set bodies.particle.velocity");
  EXPECT_TRUE(contains(yaml.message(), "invalid YAML value"));

  const InputError empty_segment =
      input_error([] { load_case(case_path("minimal.yaml"), {parse_override("solver..cfl=1")}); });
  EXPECT_TRUE(contains(empty_segment.message(), "empty name in the key path"));
}

}  // namespace
}  // namespace coldspray::case_file
