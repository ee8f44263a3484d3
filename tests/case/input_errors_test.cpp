// Every class of mistake a case file can hold gives an InputError naming FILE:LINE:COLUMN and
// the key path.
#include <gtest/gtest.h>

#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::input_error;

struct Expected {
  const char* file;
  const char* position;  // LINE:COLUMN
  const char* key;
  std::string message;  // part of the message
};

void expect_error(const Expected& x, const std::vector<Override>& overrides = {}) {
  SCOPED_TRACE(x.file);
  const InputError e = input_error([&] { load_case(case_path(x.file), overrides); });
  EXPECT_EQ(e.where(), case_path(x.file) + ":" + x.position);
  EXPECT_EQ(e.key(), x.key);
  EXPECT_TRUE(contains(e.message(), x.message));
  const std::string key_part = e.key().empty() ? "" : "key '" + e.key() + "': ";
  EXPECT_TRUE(contains(e.what(), e.where() + ": " + key_part + x.message));
}

TEST(InputErrors, YamlSyntax) { expect_error({"syntax-error.yaml", "6:60", "", "invalid YAML"}); }

TEST(InputErrors, UnknownKeySuggestsTheClosest) {
  expect_error({"unknown-key.yaml", "7:5", "bodies.particle.spaceing",
                "unknown key 'spaceing'; did you mean 'spacing'?"});
}

// A retired key says what replaced it, not just "unknown key".
TEST(InputErrors, RetiredKeyNamesItsReplacement) {
  expect_error({"retired-key.yaml", "13:3", "metrics.bonded_rest_speed",
                "was removed: the bonded verdict no longer reads v_rest at one instant"});
  const InputError e = input_error([] { load_case(case_path("retired-key.yaml")); });
  EXPECT_TRUE(contains(e.message(), "; use metrics.bonded_separation_speed (default 2 m/s)"));
}

TEST(InputErrors, ListWhereAQuantityIsExpected) {
  expect_error({"list-for-quantity.yaml", "6:57", "bodies.particle.shape.radius",
                "expected a length such as '1 m', got a list"});
}

TEST(InputErrors, TextWhereANumberIsExpected) {
  expect_error({"text-for-number.yaml", "12:8", "solver.cfl", "'fast' is not a number"});
}

TEST(InputErrors, UnitOfTheWrongDimension) {
  expect_error({"wrong-dimension.yaml", "6:57", "bodies.particle.shape.radius",
                "expected a length (m), got a velocity (m/s)"});
}

TEST(InputErrors, MissingRequiredKeyPointsAtItsMap) {
  expect_error(
      {"missing-key.yaml", "4:5", "bodies.particle.spacing", "missing required key 'spacing'"});
}

TEST(InputErrors, NonPhysicalValues) {
  expect_error({"negative-radius.yaml", "6:57", "bodies.particle.shape.radius",
                "must be > 0, got '-7 um' (-7e-06 m)"});
  expect_error({"cfl-too-large.yaml", "12:8", "solver.cfl",
                "must be in (0, 1] with solver.method mpm, got '1.5'"});
  expect_error({"bad-poisson.yaml", "6:54", "materials.rubbery.elastic.poisson_ratio",
                "must be in (-1, 0.5), got '0.5'"});
  expect_error({"grid-min-max.yaml", "11:8", "grid.max", "must be greater than min in x and z"});
  expect_error(
      {"grid-min-max-y.yaml", "11:8", "grid.max", "must be greater than min in y in 3D geometry"});
}

TEST(InputErrors, NonPhysicalValuesGivenByOverride) {
  struct Bad {
    const char* set;
    const char* key;
    const char* message;
  };
  const Bad cases[] = {
      {"materials.m.density=0 kg/m^3", "materials.m.density", "must be > 0"},
      {"bodies.particle.spacing=-1 um", "bodies.particle.spacing", "must be > 0"},
      {"bodies.particle.temperature=0 K", "bodies.particle.temperature", "must be > 0"},
      {"materials.m.taylor_quinney=1.2", "materials.m.taylor_quinney", "must be in [0, 1]"},
      {"solver.cfl=0", "solver.cfl", "must be in (0, 3]"},
      {"solver.cfl=1.5", "solver.cfl", "must be in (0, 1] with solver.method mpm"},
      {"solver.end_time=-1 ns", "solver.end_time", "must be > 0"},
      {"output.history_interval=-1 ns", "output.history_interval", "must be >= 0"},
      {"contact.mpm.friction=-0.1", "contact.mpm.friction", "must be >= 0"},
      {"metrics.bonded_separation_speed=0 m/s", "metrics.bonded_separation_speed", "must be > 0"},
      {"metrics.verdict_window=0 ns", "metrics.verdict_window", "must be > 0"},
  };
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.set);
    const Override o = parse_override(bad.set);
    const InputError e = input_error([&] {
      load_case(case_path("minimal.yaml"), {parse_override("materials.m={base: al-ptw}"),
                                            parse_override("bodies.particle.material=m"), o});
    });
    EXPECT_EQ(e.where(), "--set " + o.key);
    EXPECT_EQ(e.key(), bad.key);
    EXPECT_TRUE(contains(e.message(), bad.message));
  }
}

TEST(InputErrors, UnknownMaterialOrBase) {
  expect_error({"unknown-material.yaml", "5:15", "bodies.particle.material",
                "unknown material 'al-ptq'; did you mean 'al-ptw'?"});
  expect_error({"unknown-base.yaml", "5:11", "materials.my-al.base",
                "unknown built-in material 'al-pt'; did you mean 'al-ptw'?"});
}

TEST(InputErrors, DuplicateBodyOrProbeName) {
  expect_error(
      {"duplicate-body.yaml", "8:11", "bodies.particle.name",
       "duplicate name 'particle' (first given at " + case_path("duplicate-body.yaml") + ":4:11)"});
  expect_error({"duplicate-probe.yaml", "15:14", "output.probes.p1.name", "duplicate name 'p1'"});
}

TEST(InputErrors, ContactNormalBodyNotFound) {
  expect_error({"contact-body.yaml", "14:13", "contact.mpm.normal", "unknown body 'substrate'"});
}

TEST(InputErrors, SpacingLargerThanTheGridCell) {
  expect_error({"spacing-too-large.yaml", "7:14", "bodies.particle.spacing",
                "must not exceed grid.cell_size"});
}

TEST(InputErrors, AxisymmetricBodiesMustBeSymmetricAboutZ) {
  expect_error({"axisymmetric-box.yaml", "6:19", "bodies.plate.shape.type",
                "a box is not symmetric about the z axis"});
  expect_error({"axisymmetric-off-axis.yaml", "6:35", "bodies.particle.shape.center",
                "must lie on the z axis"});
  const InputError e = input_error([] {
    load_case(case_path("axisymmetric.yaml"),
              {parse_override("bodies.particle.velocity=[10 m/s, 0, -810 m/s]")});
  });
  EXPECT_EQ(e.where(), "--set bodies.particle.velocity");
  EXPECT_EQ(e.key(), "bodies.particle.velocity");
  EXPECT_TRUE(contains(e.message(), "must be along z"));
  // One component set: the vector's problem is that --set's, not the file line's.
  const InputError component = input_error([] {
    load_case(case_path("axisymmetric.yaml"),
              {parse_override("bodies.particle.velocity.0=10 m/s")});
  });
  EXPECT_EQ(component.where(), "--set bodies.particle.velocity.0");
  EXPECT_EQ(component.key(), "bodies.particle.velocity");
  const InputError cylinder = input_error([] {
    load_case(case_path("axisymmetric.yaml"),
              {parse_override("bodies.substrate.shape.base_center=[0, 1 um, 0]")});
  });
  EXPECT_EQ(cylinder.key(), "bodies.substrate.shape.base_center");
}

// r-z runs do not use y: a flat y range is fine there.
TEST(InputErrors, AxisymmetricGridIgnoresY) {
  const Case c =
      load_case(case_path("grid-min-max-y.yaml"), {parse_override("solver.geometry=axisymmetric")});
  EXPECT_EQ((*c.grid->max)[1], 0.0);
}

TEST(InputErrors, FileNotFound) {
  const InputError e = input_error([] { load_case(case_path("no-such-case.yaml")); });
  EXPECT_EQ(e.where(), case_path("no-such-case.yaml"));
  EXPECT_EQ(e.message(), "no such file");
}

// More mistakes, made by overriding a valid case: each is located at "--set KEY".
TEST(InputErrors, OtherMistakes) {
  struct Bad {
    std::vector<const char*> sets;
    const char* key;
    const char* message;
  };
  const Bad cases[] = {
      {{"bodies.particle.shape={type: cube, radius: 7 um}"},
       "bodies.particle.shape.type",
       "unknown type 'cube'"},
      {{"bodies.particle.shape={center: [0, 0, 0], radius: 7 um}"},
       "bodies.particle.shape.type",
       "missing required key 'type' (one of: sphere, cylinder, box)"},
      {{"bodies.particle.shape={type: sphere, center: [0, 0], radius: 7 um}"},
       "bodies.particle.shape.center",
       "expected a list of 3 values [x, y, z], got 2 values"},
      {{"bodies.particle.velocity=[0, 0, -810 m]"},
       "bodies.particle.velocity",
       "z: expected a velocity (m/s), got a length (m)"},
      {{"bodies.particle.absorbing=[bottom, bottom]"},
       "bodies.particle.absorbing",
       "'bottom' is listed twice"},
      {{"bodies.particle.fixed=[botom]"},
       "bodies.particle.fixed",
       "unknown value 'botom'; did you mean 'bottom'?"},
      {{"solver.shape_function=gimpp"}, "solver.shape_function", "did you mean 'gimp'?"},
      {{"solver.artificial_viscosity.enabled=maybe"},
       "solver.artificial_viscosity.enabled",
       "expected true or false"},
      {{"contact.mpm.normal='body:'"}, "contact.mpm.normal", "unknown contact normal 'body:'"},
      {{"grid.faces={xmn: fixed}"}, "grid.faces.xmn", "did you mean 'xmin'?"},
      {{"grid.faces={xmin: glued}"}, "grid.faces.xmin", "unknown value 'glued'"},
      {{"grid.min=[0, 0, 0]"}, "grid.min", "give both grid.min and grid.max, or neither"},
      {{"output.probes=[{name: p, position: [0, 0, 0], fields: [presure]}]"},
       "output.probes.p.fields",
       "did you mean 'pressure'?"},
      {{"output.probes=[{name: p, position: [0, 0, 0], fields: []}]"},
       "output.probes.p.fields",
       "needs at least one field"},
      {{"bodies=[]"}, "bodies", "needs at least one body"},
      {{"metrics.verdict_extensions=1.5"},
       "metrics.verdict_extensions",
       "expected a whole number >= 0, got '1.5'"},
      {{"metrics.verdict_extensions=-1"},
       "metrics.verdict_extensions",
       "expected a whole number >= 0, got '-1'"},
      {{"metrics.bonded_pbcp=5"},
       "metrics.bonded_pbcp",
       "was removed: PBCP does not separate bonded from rebounding particles"},
      {{"name=a/b"}, "name", "must be usable as a folder name"},
      {{"solver=7"}, "solver", "expected a map of keys, got text '7'"},
      {{"materials.m={base: al-ptw, elastic: {shear_modulus: 1 GPa, youngs_modulus: 2 GPa}}",
        "bodies.particle.material=m"},
       "materials.m.elastic",
       "give either {shear_modulus, bulk_modulus} or"},
      {{"materials.m={base: al-ptw, strength: {model: ptx}}", "bodies.particle.material=m"},
       "materials.m.strength.model",
       "unknown model 'ptx'; did you mean 'ptw'?"},
      {{"materials.m={base: al-ptw, strength: {model: johnson-cook, A: 1 MPa}}",
        "bodies.particle.material=m"},
       "materials.m.strength.B",
       "missing required key 'B'"},
      {{"materials.m={base: al-ptw, strength: {y0: 0.5}}", "bodies.particle.material=m"},
       "materials.m.strength.y0",
       "PTW needs y0 <= s0"},
      {{"materials.m={base: al-ptw, sources: {densty: x}}", "bodies.particle.material=m"},
       "materials.m.sources.densty",
       "did you mean 'density'?"},
  };
  for (const Bad& bad : cases) {
    std::vector<Override> overrides;
    for (const char* s : bad.sets) overrides.push_back(parse_override(s));
    SCOPED_TRACE(overrides.front().key);
    const InputError e = input_error([&] { load_case(case_path("minimal.yaml"), overrides); });
    EXPECT_EQ(e.where(), "--set " + overrides.front().key);
    EXPECT_EQ(e.key(), bad.key);
    EXPECT_TRUE(contains(e.message(), bad.message));
  }
}

TEST(InputErrors, DuplicateYamlKey) {
  const InputError e = input_error([] {
    load_case(case_path("minimal.yaml"),
              {parse_override("grid={cell_size: 1 um, cell_size: 2 um}")});
  });
  EXPECT_EQ(e.key(), "grid.cell_size");
  EXPECT_TRUE(contains(e.message(), "duplicate key 'cell_size'"));
}

}  // namespace
}  // namespace coldspray::case_file
