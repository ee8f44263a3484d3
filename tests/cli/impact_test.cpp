// `coldspray impact`: the generated particle-on-cylinder case (thesis §5.2.2, Table 5.3), its
// errors, a short run, and the examples in examples/coldspray/ that were generated with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "case/load.hpp"
#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kCommandExamples = fs::path(COLDSPRAY_SOURCE_DIR) / "examples" / "coldspray";
const std::string kCase22 = "impact --material al-ptw --diameter 22um --velocity 790m/s";

std::vector<fs::path> example_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kCommandExamples))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  return files;
}

// Writes the case of `args` with --write-case and reads it back.
case_file::Case written_case(const std::string& args) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray(args + " --write-case case.yaml", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  return case_file::load_case((fs::path(dir) / "case.yaml").string());
}

// The default set-up is in proportion to the diameter (docs/impact.md, "The set-up"): 22 um at
// 790 m/s on a 66 x 33 um cylinder, cells 22 / 40 um, the thesis' 14 um times x 22 / 14 and the
// end a window after 2 d / v.
TEST(Impact, WriteCaseGivesTheSimilarSetUpAndPassesCheck) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray(kCase22 + " --write-case case.yaml", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(fs::path(dir) / "out")) << "--write-case must not run";
  const auto check = run_coldspray("check case.yaml", dir);
  EXPECT_EQ(check.status, 0) << check.output;

  const case_file::Case c = case_file::load_case((fs::path(dir) / "case.yaml").string());
  EXPECT_EQ(c.name, "impact-al-ptw-22um-790");
  ASSERT_EQ(c.bodies.size(), 2u);
  const auto& particle = std::get<geometry::Sphere>(c.bodies[0].shape);
  EXPECT_DOUBLE_EQ(particle.radius, 11e-6);
  EXPECT_DOUBLE_EQ(particle.center.z(), 11e-6);  // touching the substrate's top z = 0
  EXPECT_DOUBLE_EQ(c.bodies[0].velocity.z(), -790.0);
  EXPECT_DOUBLE_EQ(c.bodies[0].temperature, 298.0);
  const auto& substrate = std::get<geometry::Cylinder>(c.bodies[1].shape);
  EXPECT_DOUBLE_EQ(substrate.radius, 44e-6);  // 4 d across
  EXPECT_DOUBLE_EQ(substrate.height, 44e-6);  // 2 d high
  EXPECT_DOUBLE_EQ(substrate.base_center.z() + substrate.height, 0.0);
  EXPECT_EQ(c.bodies[1].absorbing.size(), 2u);
  EXPECT_DOUBLE_EQ(c.grid->cell_size, 0.55e-6);  // D/40
  for (const auto& b : c.bodies) EXPECT_DOUBLE_EQ(b.spacing, 0.1375e-6);
  EXPECT_EQ(c.solver.geometry, case_file::Geometry::Axisymmetric);
  // Times are written in ns to 12 significant digits (cli/case_text.hpp).
  const double scale = 22.0 / 14.0, end = 20e-9 * scale + 2.0 * 22e-6 / 790.0;
  EXPECT_NEAR(c.metrics.verdict_window, 20e-9 * scale, 1e-11 * 20e-9 * scale);
  EXPECT_NEAR(c.solver.end_time, end, 1e-11 * end);
  EXPECT_NEAR(c.output.history_interval, 0.5e-9 * scale, 1e-11 * 0.5e-9 * scale);
  EXPECT_NEAR(c.output.snapshot_interval, 10e-9 * scale, 1e-11 * 10e-9 * scale);
  EXPECT_EQ(c.contact.mpm.normal_body, "substrate");
  // Energy bonding with the schema's parameters (the project's calibration).
  case_file::Bonding energy;
  energy.model = case_file::BondingModel::Energy;
  EXPECT_EQ(c.bonding, energy);
}

// --setup thesis: thesis Table 5.3's substrate, the 0.7/0.175 um grid and 80 ns; --resolution
// sets the cells per diameter of the similar set-up.
TEST(Impact, TheThesisSetUpAndTheResolution) {
  const case_file::Case c = written_case(kCase22 + " --setup thesis");
  const auto& substrate = std::get<geometry::Cylinder>(c.bodies[1].shape);
  EXPECT_DOUBLE_EQ(substrate.radius, 22e-6);  // Table 5.3: 44 um across for 22 um
  EXPECT_DOUBLE_EQ(substrate.height, 10e-6);
  EXPECT_DOUBLE_EQ(c.grid->cell_size, 0.7e-6);
  for (const auto& b : c.bodies) EXPECT_DOUBLE_EQ(b.spacing, 0.175e-6);
  EXPECT_DOUBLE_EQ(c.solver.end_time, 80e-9);
  EXPECT_DOUBLE_EQ(c.metrics.verdict_window, 20e-9);
  EXPECT_DOUBLE_EQ(c.output.history_interval, 0.5e-9);
  EXPECT_DOUBLE_EQ(c.output.snapshot_interval, 10e-9);

  const case_file::Case fine = written_case(kCase22 + " --resolution D/80");
  EXPECT_DOUBLE_EQ(fine.grid->cell_size, 22e-6 / 80.0);
  EXPECT_DOUBLE_EQ(fine.bodies[0].spacing, 22e-6 / 320.0);
  const std::string dir = make_temp_dir("impact-resolution");
  for (const std::string bad :
       {"--resolution 40", "--resolution D/1", "--resolution D/40um", "--resolution 0.7um/0.175um",
        "--resolution D/40 --grid 1um/0.25um", "--solver peridynamics --resolution D/40"}) {
    const auto r = run_coldspray(kCase22 + " " + bad + " --write-case case.yaml", dir);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find(bad.find("--grid") != std::string::npos ? "not both" : "--resolution"),
              std::string::npos)
        << bad << "\n"
        << r.output;
  }
}

TEST(Impact, OptionsReachTheCase) {
  const case_file::Case c = written_case(
      kCase22 +
      " --grid 1um/0.25um --bonding strain --eps-c 1.2 --eps-c-rate '8e8 1/s' --Gc 1400J/m^2 "
      "--Gc-rate 2J/m^2/us --floor 0.2 --end-time 60ns --shape-function linear "
      "--substrate-material cu-ptw --set solver.cfl=0.2");
  EXPECT_DOUBLE_EQ(c.grid->cell_size, 1e-6);
  EXPECT_DOUBLE_EQ(c.bodies[1].spacing, 0.25e-6);
  EXPECT_EQ(c.bodies[1].material, "cu-ptw");
  EXPECT_EQ(c.bonding.model, case_file::BondingModel::Strain);
  EXPECT_DOUBLE_EQ(c.bonding.critical_strain, 1.2);
  EXPECT_DOUBLE_EQ(c.bonding.critical_strain_rate, 8e8);
  EXPECT_DOUBLE_EQ(c.bonding.critical_energy, 1400.0);
  EXPECT_DOUBLE_EQ(c.bonding.critical_energy_rate, 2e6);
  EXPECT_DOUBLE_EQ(c.bonding.floor, 0.2);
  EXPECT_DOUBLE_EQ(c.solver.end_time, 60e-9);
  EXPECT_EQ(c.solver.shape_function, case_file::ShapeFunction::Linear);
  EXPECT_DOUBLE_EQ(c.solver.cfl, 0.2);  // --set edits the generated case
}

TEST(Impact, ThreeDIsAQuarterModelOnSymmetryPlanes) {
  const case_file::Case c =
      written_case(kCase22 + " --geometry 3d --grid 1um/0.25um --setup thesis");
  EXPECT_EQ(c.solver.geometry, case_file::Geometry::ThreeD);
  ASSERT_TRUE(c.grid->min.has_value());
  EXPECT_EQ(c.grid->min->x(), 0.0);
  EXPECT_EQ(c.grid->min->y(), 0.0);
  EXPECT_EQ(c.grid->faces.at(case_file::GridFace::XMin), case_file::FaceCondition::Roller);
  EXPECT_EQ(c.grid->faces.at(case_file::GridFace::YMin), case_file::FaceCondition::Roller);
  // The substrate's rim and the rebound stay on the grid: the solver's own margin (half the
  // extent) around the 22 um wide, 32 um tall quarter, snapped to whole cells.
  EXPECT_NEAR(c.grid->max->x(), 33e-6, 1e-12);
  EXPECT_NEAR(c.grid->min->z(), -26e-6, 1e-12);
  EXPECT_NEAR(c.grid->max->z(), 38e-6, 1e-12);

  // The similar set-up's 3D default is D/20 (impact_case.hpp), r-z's D/40.
  const case_file::Case similar = written_case(kCase22 + " --geometry 3d");
  EXPECT_DOUBLE_EQ(similar.grid->cell_size, 22e-6 / 20);
  for (const auto& b : similar.bodies) EXPECT_DOUBLE_EQ(b.spacing, 22e-6 / 80);

  const case_file::Case whole =
      written_case(kCase22 + " --geometry 3d --symmetry none --setup thesis");
  EXPECT_FALSE(whole.grid->min.has_value());
  EXPECT_EQ(whole.grid->faces.at(case_file::GridFace::XMin), case_file::FaceCondition::Free);
}

// --coarsening L: the substrate's coarsened seeding (docs/mpm.md), fine within 0.65 D of the
// axis and 0.36 D of its top; by default 2 levels (to the cell) in the similar set-up, as many
// as fit an absolute grid's cell, none in the thesis'; too many levels for the cell name the
// option; PD refuses it.
TEST(Impact, CoarseningReachesTheSubstrate) {
  const case_file::Case c = written_case(kCase22 + " --geometry 3d --coarsening 1");
  ASSERT_TRUE(c.bodies[1].coarsening);
  EXPECT_FALSE(c.bodies[0].coarsening);
  EXPECT_EQ(c.bodies[1].coarsening->levels, 1);
  const auto& fine = std::get<geometry::Cylinder>(c.bodies[1].coarsening->fine);
  EXPECT_NEAR(fine.radius, 0.65 * 22e-6, 1e-12);
  EXPECT_NEAR(fine.height, 0.36 * 22e-6, 1e-12);
  EXPECT_NEAR(fine.base_center.z(), -0.36 * 22e-6, 1e-12);
  const case_file::Case similar = written_case(kCase22);
  ASSERT_TRUE(similar.bodies[1].coarsening);
  EXPECT_EQ(similar.bodies[1].coarsening->levels, 2);
  const case_file::Case half = written_case(kCase22 + " --grid 1um/0.5um");
  ASSERT_TRUE(half.bodies[1].coarsening);
  EXPECT_EQ(half.bodies[1].coarsening->levels, 1);
  EXPECT_FALSE(written_case(kCase22 + " --coarsening 0").bodies[1].coarsening);
  EXPECT_FALSE(written_case(kCase22 + " --setup thesis").bodies[1].coarsening);
  const auto coarse = run_coldspray(kCase22 + " --coarsening 3");
  EXPECT_EQ(coarse.status, 2) << coarse.output;
  EXPECT_NE(coarse.output.find("--coarsening: key 'bodies.substrate.coarsening.levels'"),
            std::string::npos)
      << coarse.output;
  const auto pd = run_coldspray(
      "impact --solver peridynamics --diameter 10um --velocity 500m/s --coarsening 1");
  EXPECT_EQ(pd.status, 2) << pd.output;
  EXPECT_NE(pd.output.find("--coarsening: is the MPM's option"), std::string::npos) << pd.output;
}

// --solver peridynamics: the PD paper's set-up (its "Simulation Setup"): cu-jc by default, a
// cylinder of radius and height 4 particle radii, bottom fixed, side restrained, D / 50
// spacing, a quarter by symmetry planes.
TEST(Impact, PeridynamicsBuildsThePdPapersSetUp) {
  const case_file::Case c =
      written_case("impact --solver peridynamics --diameter 30um --velocity 500m/s");
  EXPECT_EQ(c.solver.method, case_file::Method::Peridynamics);
  EXPECT_EQ(c.solver.geometry, case_file::Geometry::ThreeD);
  EXPECT_EQ(c.bodies.at(0).material, "cu-jc");
  EXPECT_EQ(c.bodies.at(1).material, "cu-jc");
  EXPECT_NEAR(c.bodies.at(0).spacing, 0.6e-6, 1e-15);
  const auto& cylinder = std::get<geometry::Cylinder>(c.bodies.at(1).shape);
  EXPECT_NEAR(cylinder.radius, 60e-6, 1e-15);
  EXPECT_NEAR(cylinder.height, 60e-6, 1e-15);
  EXPECT_NEAR(cylinder.base_center.z(), -60e-6, 1e-15);
  EXPECT_EQ(c.bodies.at(1).fixed, std::vector<case_file::BodyFace>{case_file::BodyFace::Bottom});
  EXPECT_EQ(c.bodies.at(1).roller, std::vector<case_file::BodyFace>{case_file::BodyFace::Side});
  ASSERT_TRUE(c.symmetry.has_value());
  EXPECT_EQ(c.symmetry->x, 0.0);
  EXPECT_EQ(c.symmetry->y, 0.0);
  EXPECT_EQ(c.bonding.model, case_file::BondingModel::None);
  EXPECT_FALSE(c.grid.has_value());

  const case_file::Case whole = written_case(
      "impact --solver peridynamics --diameter 30um --velocity 500m/s --symmetry none "
      "--spacing 1um --material al-jc");
  EXPECT_FALSE(whole.symmetry.has_value());
  EXPECT_NEAR(whole.bodies.at(1).spacing, 1e-6, 1e-15);
  EXPECT_EQ(whole.bodies.at(1).material, "al-jc");
}

// --contact lennard-jones: the PD paper's contact model 1, the particle lifted by whole spacings
// until its nearest points are a cut-off (2.75 x 1.1 spacings = 3.025) from the substrate's:
// 3 spacings, 4 between the nearest points.
TEST(Impact, ContactModelOneLiftsTheParticleToItsCutOff) {
  const case_file::Case c = written_case(
      "impact --solver peridynamics --diameter 30um --velocity 500m/s --spacing 1.2um "
      "--contact lennard-jones --beta 0.004");
  EXPECT_EQ(c.contact.peridynamics.model, case_file::ContactModel::LennardJones);
  EXPECT_EQ(c.contact.peridynamics.beta, 0.004);
  EXPECT_NEAR(std::get<geometry::Sphere>(c.bodies.at(0).shape).center.z(), 15e-6 + 3.6e-6, 1e-15);
  const case_file::Case repulsive =
      written_case("impact --solver peridynamics --diameter 30um --velocity 500m/s");
  EXPECT_EQ(repulsive.contact.peridynamics.model, case_file::ContactModel::Repulsive);
  EXPECT_NEAR(std::get<geometry::Sphere>(repulsive.bodies.at(0).shape).center.z(), 15e-6, 1e-15);
}

// Model 1 on bodies seeded touching would push them apart at t = 0 with (r0/r)^13: refused.
TEST(Impact, ContactModelOneRefusesBodiesCloserThanItsEquilibrium) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray("run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                                   "/examples/verification/pd-quarter-impact.yaml' --set "
                                   "contact.peridynamics.model=lennard-jones",
                               dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("contact.peridynamics.model"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("closer than the Lennard-Jones equilibrium distance"), std::string::npos)
      << r.output;
}

// Model 2 takes the interface's G_c from the materials' surface energies: a material without one
// needs contact.peridynamics.fracture_energy.
TEST(Impact, ContactModelTwoNeedsAFractureEnergy) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray("run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                                   "/examples/verification/pd-elastic-wave.yaml' --set "
                                   "contact.peridynamics.model=interface-bonds",
                               dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("contact.peridynamics.fracture_energy"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'elastic-al'"), std::string::npos) << r.output;
}

// In peridynamics an adhesive contact decides the verdict: the bonded area is what it holds. The
// blocks of tests/data/cli/pd-bonded-blocks.yaml settle onto each other at 0.01 m/s: held by
// contact model 2's 36 bonds (36 um^2), bonded; with the repulsion alone, nothing holds them.
TEST(Impact, AnAdhesiveContactDecidesThePeridynamicVerdict) {
  const std::string dir = make_temp_dir("impact");
  const std::string run = "run '" + std::string(COLDSPRAY_TEST_DATA) +
                          "/cli/pd-bonded-blocks.yaml' --quiet --set solver.end_time=4ns "
                          "--set metrics.verdict_window=2ns";
  for (const auto& [model, outcome, area] :
       std::vector<std::tuple<std::string, std::string, double>>{
           {"interface-bonds", "bonded", 36e-12}, {"repulsive", "rebounded", 0.0}}) {
    const auto r =
        run_coldspray(run + " --out " + model + " --set contact.peridynamics.model=" + model, dir);
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(fs::path(dir) / model / "summary.json");
    const nlohmann::json block = nlohmann::json::parse(in)["bodies"]["block"];
    EXPECT_EQ(block["verdict"]["outcome"], outcome) << model;
    EXPECT_NEAR(block["bonded_area"].get<double>(), area, 1e-6 * 36e-12) << model;
  }
}

TEST(Impact, SolverOptionsThatDoNotFitAreBadInput) {
  const std::string pd = "impact --solver peridynamics --diameter 10um --velocity 500m/s";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {pd + " --bonding energy", "--bonding: the direct bonding model is the MPM's"},
           {pd + " --geometry axisymmetric", "--geometry: peridynamics runs in 3d only"},
           {pd + " --spacing 5um", "--spacing: the spacing (5 um) must be at most a quarter"},
           {"impact --diameter 10um --velocity 500m/s", "--material: required with --solver mpm"},
           {kCase22 + " --spacing 1um", "--spacing: is peridynamics' option"},
           {kCase22 + " --contact lennard-jones", "--contact: is peridynamics' option"},
           {pd + " --beta 0.004", "--beta: is the parameter of --contact lennard-jones"},
           {pd + " --contact lennard-jones --beta 0", "--beta: must be in (0, 1)"}}) {
    const auto r = run_coldspray(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
}

TEST(Impact, UnknownMaterialNamesTheOption) {
  const std::string dir = make_temp_dir("impact");
  const auto r =
      run_coldspray("impact --material unobtainium --diameter 22um --velocity 790m/s", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--material"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("unobtainium"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Impact, VelocityWithTheWrongUnitIsBadInput) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray("impact --material al-ptw --diameter 22um --velocity 5kg", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--velocity"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Impact, SchemaErrorsNameTheOptionThatGaveTheValue) {
  // The same checks as a case file, reported at the option rather than a generated line.
  const auto spacing = run_coldspray(kCase22 + " --grid 1um/2um");
  EXPECT_EQ(spacing.status, 2) << spacing.output;
  EXPECT_NE(spacing.output.find("--grid: key 'bodies.particle.spacing'"), std::string::npos)
      << spacing.output;
  const auto floor = run_coldspray(kCase22 + " --floor 2");
  EXPECT_EQ(floor.status, 2) << floor.output;
  EXPECT_NE(floor.output.find("--floor: key 'bonding.floor'"), std::string::npos) << floor.output;
  const auto geometry = run_coldspray(kCase22 + " --geometry 2d");
  EXPECT_EQ(geometry.status, 2) << geometry.output;
}

// `coldspray impact OPTIONS --out result --quiet --threads 1` in a fresh folder: what it printed
// and its summary.json (null if it failed).
struct ImpactRun {
  std::string output;
  nlohmann::json summary;
};
ImpactRun run_impact(const std::string& options) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray("impact " + options + " --out result --quiet --threads 1", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const fs::path summary = fs::path(dir) / "result" / "summary.json";
  return {r.output,
          fs::exists(summary) ? nlohmann::json::parse(read_text(summary)) : nlohmann::json()};
}

// 2 ns is shorter than the 20 ns window, and with no extension allowed the run ends there:
// undecided, read over the whole run, in which the particle is still moving in (a negative mean
// separation speed) and has no bond yet.
TEST(Impact, TinyRunWritesTheSummaryAndPrintsTheVerdict) {
  const ImpactRun r = run_impact(
      "--material al-ptw --diameter 4um --grid 1um/0.5um --end-time 2ns --velocity 500m/s "
      "--set metrics.verdict_extensions=0");
  for (const char* field :
       {"verdict: UNDECIDED (mean separation speed -", " m/s over the last 2 ns, margin ",
        "; bonded area 0 um^2)", "cor ", "v_rest ", "pbcp ", "jetted ", "results in result/"})
    EXPECT_NE(r.output.find(field), std::string::npos) << field << "\n" << r.output;
  ASSERT_TRUE(r.summary.is_object());
  EXPECT_EQ(r.summary["system"]["outcome"], "undecided");
  EXPECT_EQ(r.summary["system"]["bonded"], false);
  EXPECT_EQ(r.summary["bodies"]["particle"]["verdict"]["outcome"], "undecided");
  EXPECT_FALSE(r.summary["bodies"]["substrate"].contains("verdict"));
}

// A 6 um particle bonding at once (G_c = 1 J/m^2, no activation needed, the thesis' model and
// set-up): at 10 ns its 10 ns window still holds the impact, so the run goes on a window, to
// 20 ns, where it reads bonded, the margin (threshold - mean) positive. (Before the absorbing
// dashpots acted on the grid's velocity the particle was still being pulled back at 20 ns and
// took a second window.)
TEST(Impact, AnUndecidedRunIsExtendedAndReadsBonded) {
  const ImpactRun r = run_impact(
      "--material al-ptw --diameter 6um --velocity 800m/s --grid 0.5um/0.125um --Gc 1J/m^2 "
      "--setup thesis --end-time 10ns --set metrics.verdict_window=10ns "
      "--set bonding.critical_penetration=0");
  EXPECT_NE(r.output.find("verdict: BONDED after 1 extension to 20 ns (mean separation speed "),
            std::string::npos)
      << r.output;
  ASSERT_TRUE(r.summary.is_object());
  const nlohmann::json& v = r.summary["bodies"]["particle"]["verdict"];
  EXPECT_EQ(r.summary["system"]["outcome"], "bonded");
  EXPECT_EQ(r.summary["system"]["extensions"], 1);
  EXPECT_NEAR(r.summary["time"].get<double>(), 20e-9, 1e-18);
  EXPECT_NEAR(v["window"].get<double>(), 10e-9, 1e-18);
  EXPECT_NEAR(v["margin"].get<double>(), 2.0 - v["separation_speed"].get<double>(), 1e-12);
  EXPECT_GT(v["margin"].get<double>(), 0.0);
}

// summary.json's bonded area by partner and the system's PBCP (docs/bonding.md, "Metrics"), on
// a particle that bonds in part at once (G_c = 20 J/m^2, 2 ns): with two bodies each holds all its
// bonded area to the other, and the system's PBCP, eq 5.1 over both bodies' contacted points, lies
// between theirs.
TEST(Impact, SummaryHasBondedAreaByPartnerAndTheSystemsPbcp) {
  const std::string dir = make_temp_dir("impact");
  const auto r = run_coldspray("run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                                   "/examples/verification/bonding-impact.yaml' --out result "
                                   "--quiet --set solver.end_time=2ns --set "
                                   "bonding.critical_energy=20J/m^2",
                               dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(read_text(fs::path(dir) / "result" / "summary.json"));
  const auto& particle = j["bodies"]["particle"];
  const auto& substrate = j["bodies"]["substrate"];
  ASSERT_GT(particle["bonded_area"].get<double>(), 0.0);
  EXPECT_EQ(particle["bonded_area_with"].size(), 1u);
  EXPECT_EQ(particle["bonded_area_with"]["substrate"].get<double>(),
            particle["bonded_area"].get<double>());
  EXPECT_EQ(substrate["bonded_area_with"]["particle"].get<double>(),
            substrate["bonded_area"].get<double>());
  const double low = std::min(particle["pbcp"].get<double>(), substrate["pbcp"].get<double>());
  const double high = std::max(particle["pbcp"].get<double>(), substrate["pbcp"].get<double>());
  const double system = j["system"]["pbcp"].get<double>();
  EXPECT_LT(low, high);
  EXPECT_GE(system, low);
  EXPECT_LE(system, high);
}

TEST(ImpactExamples, EveryExamplePassesCheck) {
  const std::vector<fs::path> files = example_files();
  EXPECT_GE(files.size(), 8u);
  for (const fs::path& file : files) {
    const auto r = run_coldspray("check '" + file.string() + "'");
    EXPECT_EQ(r.status, 0) << file << "\n" << r.output;
  }
}

// Each example says on its first line the command that generated it; the command still gives
// the same case, so the examples and `coldspray impact` agree.
TEST(ImpactExamples, EveryExampleIsWhatItsCommandGenerates) {
  const std::string prefix = "# Generated by: coldspray ";
  for (const fs::path& file : example_files()) {
    const std::string text = read_text(file);
    const auto start = text.find(prefix);
    ASSERT_NE(start, std::string::npos) << file;
    const auto end = text.find('\n', start);
    const std::string args = text.substr(start + prefix.size(), end - start - prefix.size());
    const case_file::Case expected = written_case(args);
    const case_file::Case example = case_file::load_case(file.string());
    EXPECT_EQ(example.name, expected.name) << file;
    EXPECT_EQ(example.bodies, expected.bodies) << file;
    EXPECT_EQ(example.grid, expected.grid) << file;
    EXPECT_EQ(example.solver, expected.solver) << file;
    EXPECT_EQ(example.contact, expected.contact) << file;
    EXPECT_EQ(example.bonding, expected.bonding) << file;
    EXPECT_EQ(example.metrics, expected.metrics) << file;
    EXPECT_EQ(example.output, expected.output) << file;
  }
}

// The energy defaults are al-ptw on al-ptw's calibration: another pair is warned about, the
// calibrated pair and a pair given its own G_c and Gdot_c are not.
TEST(ImpactCalibration, WarnsWhenThePairIsNotTheCalibratedOne) {
  const std::string dir = make_temp_dir("impact-warning");
  const std::string base = "impact --diameter 30um --velocity 500m/s --write-case case.yaml ";
  const auto copper = run_coldspray(base + "--material cu-jc", dir);
  EXPECT_EQ(copper.status, 0) << copper.output;
  EXPECT_NE(copper.output.find("warning: the energy bonding model's defaults"), std::string::npos)
      << copper.output;
  EXPECT_NE(copper.output.find("not for cu-jc on cu-jc"), std::string::npos) << copper.output;
  const auto al_on_cu = run_coldspray(base + "--material al-ptw --substrate-material cu-jc", dir);
  EXPECT_NE(al_on_cu.output.find("not for al-ptw on cu-jc"), std::string::npos) << al_on_cu.output;
  const auto aluminium = run_coldspray(base + "--material al-ptw", dir);
  EXPECT_EQ(aluminium.output.find("warning"), std::string::npos) << aluminium.output;
  const auto own =
      run_coldspray(base + "--material cu-jc --Gc 500J/m^2 --Gc-rate 1e5J/m^2/us", dir);
  EXPECT_EQ(own.output.find("warning"), std::string::npos) << own.output;
}

}  // namespace
}  // namespace coldspray::testing
