// The checks that depend on solver.method (case/validate.cpp, docs/input-reference.md "Checks
// across keys"): each gives an InputError naming the file and the key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::contains;
using testing::example;
using testing::input_error;

// The error names `key` and points at the --set that gave it, or else into the file.
void expect_error(const std::string& file, const std::vector<Override>& overrides,
                  const std::string& key, const std::string& message) {
  SCOPED_TRACE(key);
  const InputError e = input_error([&] { load_case(example(file), overrides); });
  bool from_set = false;
  for (const Override& o : overrides) from_set = from_set || o.key == key;
  EXPECT_TRUE(contains(e.where(), from_set ? "--set " + key : example(file) + ":"));
  EXPECT_EQ(e.key(), key);
  EXPECT_TRUE(contains(e.message(), message));
}

TEST(SolverSections, TheMpmNeedsAGrid) {
  expect_error("verification/pd-elastic-spheres.yaml", {{"solver.method", "mpm"}}, "grid",
               "solver.method mpm needs a grid");
}

TEST(SolverSections, PeridynamicsIsThreeDimensional) {
  expect_error("verification/pd-elastic-spheres.yaml", {{"solver.geometry", "axisymmetric"}},
               "solver.geometry", "must be 3d with solver.method peridynamics");
}

TEST(SolverSections, TheHorizonFactorLiesBetweenTwoAndSix) {
  for (const char* factor : {"1.5", "6.5"})
    expect_error("verification/pd-elastic-spheres.yaml", {{"peridynamics.horizon_factor", factor}},
                 "peridynamics.horizon_factor", "must be in [2, 6]");
}

TEST(SolverSections, UnknownPeridynamicsKeysAreErrors) {
  expect_error("verification/pd-elastic-spheres.yaml", {{"peridynamics.horizon", "3"}},
               "peridynamics.horizon", "unknown key 'horizon'");
}

TEST(SolverSections, ControlStiffnessIsElasticOrFlow) {
  expect_error("verification/pd-elastic-spheres.yaml",
               {{"peridynamics.control_stiffness", "plastic"}}, "peridynamics.control_stiffness",
               "elastic");
  const Case c = load_case(example("verification/pd-elastic-spheres.yaml"),
                           {{"peridynamics.control_stiffness", "flow"}});
  EXPECT_EQ(c.peridynamics->control_stiffness, ControlStiffness::Flow);
  EXPECT_EQ(
      load_case(example("verification/pd-elastic-spheres.yaml")).peridynamics->control_stiffness,
      ControlStiffness::Elastic);
}

TEST(SolverSections, TheBondingModelIsTheMpms) {
  expect_error("verification/pd-elastic-spheres.yaml", {{"bonding.model", "energy"}},
               "bonding.model", "must be none with solver.method peridynamics");
}

// contact.mpm.other_pairs_normal: the rule at pairs without the body contact.mpm.normal names; with
// another normal it has no pairs to act on (exit 2 naming it).
TEST(SolverSections, OtherPairsNormalGoesWithABodysNormal) {
  const Case c = load_case(example("al-14um-810.yaml"),
                           {{"contact.mpm.normal", "body:substrate"},
                            {"contact.mpm.other_pairs_normal", "average-gradient"}});
  EXPECT_EQ(c.contact.mpm.normal, ContactNormal::Body);
  EXPECT_EQ(c.contact.mpm.other_pairs_normal, ContactNormal::AverageGradient);
  EXPECT_EQ(load_case(example("al-14um-810.yaml")).contact.mpm.other_pairs_normal,
            ContactNormal::MaxGradient);
  expect_error(
      "al-14um-810.yaml",
      {{"contact.mpm.normal", "highest-id"}, {"contact.mpm.other_pairs_normal", "highest-id"}},
      "contact.mpm.other_pairs_normal", "applies with contact.mpm.normal: body:NAME only");
  expect_error("al-14um-810.yaml",
               {{"contact.mpm.normal", "body:substrate"},
                {"contact.mpm.other_pairs_normal", "body:particle"}},
               "contact.mpm.other_pairs_normal", "max-gradient");
}

TEST(SolverSections, ContactModelOneIsPeridynamicsOnly) {
  expect_error("al-14um-810.yaml", {{"contact.peridynamics.model", "lennard-jones"}},
               "contact.peridynamics.model", "is peridynamics only");
}

TEST(SolverSections, ContactModelOneParametersAreChecked) {
  const std::string spheres = "verification/pd-elastic-spheres.yaml";
  for (const char* beta : {"0", "-0.001", "1"})
    expect_error(spheres, {{"contact.peridynamics.beta", beta}}, "contact.peridynamics.beta",
                 "must be in (0, 1)");
  expect_error(spheres, {{"contact.peridynamics.r0", "0"}}, "contact.peridynamics.r0",
               "must be > 0");
  expect_error(spheres, {{"contact.peridynamics.cutoff", "1"}}, "contact.peridynamics.cutoff",
               "must be > 1");
  expect_error(spheres, {{"contact.peridynamics.alpha", "-1 J"}}, "contact.peridynamics.alpha",
               "must be > 0");
  expect_error(spheres, {{"contact.peridynamics.repulsion_exponent", "6"}},
               "contact.peridynamics.repulsion_exponent", "must exceed attraction_exponent");
  expect_error(spheres, {{"contact.peridynamics.model", "sticky"}}, "contact.peridynamics.model",
               "lennard-jones");
  const Case c = load_case(example(spheres), {{"contact.peridynamics.model", "lennard-jones"},
                                              {"contact.peridynamics.beta", "0.004"},
                                              {"contact.peridynamics.alpha", "2e-6 J"}});
  EXPECT_EQ(c.contact.peridynamics.model, ContactModel::LennardJones);
  EXPECT_EQ(c.contact.peridynamics.beta, 0.004);
  EXPECT_EQ(c.contact.peridynamics.alpha, 2e-6);
  EXPECT_EQ(c.contact.peridynamics.r0, 1.1);
  EXPECT_EQ(c.contact.peridynamics.cutoff, 2.75);
}

// Coarsened seeding (docs/mpm.md): its coarsest points no larger than a cell, and MPM only.
TEST(SolverSections, CoarseningStaysWithinACellAndIsMpmOnly) {
  const std::string fine = "{type: box, min: [0, 0, -2 um], max: [4 um, 4 um, 0]}";
  // 0.175 um x 2^3 = 1.4 um > the 0.7 um cell.
  const InputError e = input_error([&] {
    load_case(example("al-14um-810.yaml"),
              {{"bodies.substrate.coarsening", "{levels: 3, fine: " + fine + "}"}});
  });
  EXPECT_EQ(e.key(), "bodies.substrate.coarsening.levels");
  EXPECT_TRUE(contains(e.where(), "--set bodies.substrate.coarsening")) << e.where();
  EXPECT_TRUE(contains(e.message(), "larger than grid.cell_size")) << e.message();
  const Case c = load_case(example("al-14um-810.yaml"),
                           {{"bodies.substrate.coarsening", "{levels: 2, fine: " + fine + "}"}});
  ASSERT_TRUE(c.bodies[1].coarsening);
  EXPECT_EQ(c.bodies[1].coarsening->levels, 2);
  expect_error("verification/pd-elastic-spheres.yaml",
               {{"bodies.lower.coarsening", "{levels: 1, fine: " + fine + "}"}},
               "bodies.lower.coarsening", "is MPM only");
}

// The debonding law's strength and fracture energy (issue 26's bad input): not positive, exit 2
// naming the key.
TEST(SolverSections, DebondingLawParametersArePositive) {
  for (const char* strength : {"0 MPa", "-1 MPa"})
    expect_error("al-14um-810.yaml", {{"bonding.debond.strength", strength}},
                 "bonding.debond.strength", "must be > 0");
  expect_error("al-14um-810.yaml", {{"bonding.debond.fracture_energy", "0 J/m^2"}},
               "bonding.debond.fracture_energy", "must be > 0");
  const Case c = load_case(example("al-14um-810.yaml"), {{"bonding.debond.law", "cohesive"},
                                                         {"bonding.debond.strength", "50 MPa"}});
  EXPECT_EQ(c.bonding.debond.strength, 50e6);
}

TEST(SolverSections, ContactModelTwoParametersAreChecked) {
  const std::string spheres = "verification/pd-elastic-spheres.yaml";
  expect_error("al-14um-810.yaml", {{"contact.peridynamics.model", "interface-bonds"}},
               "contact.peridynamics.model", "is peridynamics only");
  for (const char* s_y : {"0", "-0.001", "1"})
    expect_error(spheres, {{"contact.peridynamics.yield_stretch", s_y}},
                 "contact.peridynamics.yield_stretch", "must be in (0, 1)");
  expect_error(spheres, {{"contact.peridynamics.softening", "0"}}, "contact.peridynamics.softening",
               "must be > 0");
  expect_error(spheres, {{"contact.peridynamics.fracture_energy", "0 J/m^2"}},
               "contact.peridynamics.fracture_energy", "must be > 0");
  const Case c = load_case(example(spheres), {{"contact.peridynamics.model", "interface-bonds"},
                                              {"contact.peridynamics.fracture_energy", "2 J/m^2"},
                                              {"contact.peridynamics.softening", "300"}});
  EXPECT_EQ(c.contact.peridynamics.model, ContactModel::InterfaceBonds);
  EXPECT_EQ(c.contact.peridynamics.fracture_energy, 2.0);
  EXPECT_EQ(c.contact.peridynamics.softening, 300.0);
  EXPECT_FALSE(c.contact.peridynamics.yield_stretch);
}

TEST(SolverSections, TheGripIsChecked) {
  const std::string spheres = "verification/pd-elastic-spheres.yaml";
  const Override velocity{"grip.velocity", "[0, 0, 1 m/s]"};
  // Both solvers take a grip (the pull-off test, docs/pull-off.md).
  const Case mpm = load_case(example("al-14um-810.yaml"), {{"grip.body", "particle"}, velocity});
  EXPECT_EQ(mpm.grip->body, "particle");
  expect_error(spheres, {{"grip.body", "middle"}, velocity}, "grip.body", "upper");
  expect_error(spheres, {{"grip.body", "upper"}, {"grip.velocity", "[0, 0, 0 m/s]"}},
               "grip.velocity", "must not be zero");
  expect_error(spheres, {{"grip.body", "upper"}, velocity, {"grip.fraction", "0"}}, "grip.fraction",
               "must be in (0, 1]");
  expect_error(spheres, {{"grip.body", "upper"}, velocity, {"grip.ramp", "-1 ns"}}, "grip.ramp",
               "must be >= 0");
  const Case c = load_case(example(spheres), {{"grip.body", "upper"}, velocity});
  ASSERT_TRUE(c.grip);
  EXPECT_EQ(c.grip->body, "upper");
  EXPECT_EQ(c.grip->fraction, 0.5);
  EXPECT_EQ(c.grip->velocity.z(), 1.0);
}

TEST(SolverSections, RollerFacesArePeridynamicsOnly) {
  expect_error("al-14um-810.yaml", {{"bodies.substrate.roller", "[side]"}},
               "bodies.substrate.roller", "is peridynamics only");
}

// One case, both solvers: the section of the solver not chosen is read but not used.
TEST(SolverSections, ACaseWithBothSectionsRunsOnEither) {
  const std::vector<Override> pd = {{"solver.method", "peridynamics"},
                                    {"solver.geometry", "3d"},
                                    {"peridynamics.horizon_factor", "4"}};
  const Case c = load_case(example("verification/sliding-impact-3d.yaml"), pd);
  EXPECT_EQ(c.solver.method, Method::Peridynamics);
  ASSERT_TRUE(c.grid.has_value());
  EXPECT_EQ(c.peridynamics->horizon_factor, 4.0);
  const Case m = load_case(example("verification/sliding-impact-3d.yaml"));
  EXPECT_EQ(m.solver.method, Method::Mpm);
  EXPECT_FALSE(m.peridynamics.has_value());
  // Without the section, a peridynamics case takes its defaults (and echoes them).
  const Case d = load_case(example("verification/pd-elastic-spheres.yaml"));
  ASSERT_TRUE(d.peridynamics.has_value());
  EXPECT_EQ(*d.peridynamics, Peridynamics{});
}

// Each solver has its own default time-step fraction (docs/pd.md, "Time step"); a given one,
// in the file or by --set, is kept.
TEST(SolverSections, TheDefaultTimeStepFractionIsTheSolvers) {
  EXPECT_EQ(load_case(example("verification/pd-elastic-spheres.yaml")).solver.cfl, 1.2);
  EXPECT_EQ(load_case(example("verification/sliding-impact-3d.yaml")).solver.cfl, 0.3);
  EXPECT_EQ(load_case(example("verification/pd-elastic-spheres.yaml"), {{"solver.cfl", "0.3"}})
                .solver.cfl,
            0.3);
  EXPECT_EQ(load_case(example("verification/plate-impact-al-500.yaml"),
                      {{"solver.method", "peridynamics"}, {"solver.geometry", "3d"}})
                .solver.cfl,
            0.3);  // the file's own cfl: 0.3
}

// Peridynamics' stable step is about 2.6 h / c (docs/pd.md, "Time step"), the MPM's h / c: a
// cfl above 1 is for peridynamics only, and 3 is the most either takes.
TEST(SolverSections, ACflAboveOneIsPeridynamicsOnly) {
  EXPECT_EQ(load_case(example("verification/pd-elastic-spheres.yaml"), {{"solver.cfl", "2.5"}})
                .solver.cfl,
            2.5);
  const auto error_of = [](const char* file, const char* cfl) {
    try {
      load_case(example(file), {{"solver.cfl", cfl}});
    } catch (const InputError& e) {
      return std::string(e.key()) + ": " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("verification/pd-elastic-spheres.yaml", "3.5"),
            "solver.cfl: must be in (0, 3], got '3.5'");
  EXPECT_EQ(error_of("verification/sliding-impact-3d.yaml", "1.5"),
            "solver.cfl: must be in (0, 1] with solver.method mpm, got '1.5' (the explicit MPM's "
            "bound is 1)");
}

}  // namespace
}  // namespace coldspray::case_file
