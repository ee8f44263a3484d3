// The contact keys split by solver (issue 54; case/moved_keys.hpp): a case file, a --set and a
// checkpoint's case text that give them the old way read as the new keys do.
#include "case/moved_keys.hpp"

#include <gtest/gtest.h>

#include "case/load.hpp"
#include "case_test_support.hpp"
#include "read_text.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::example;
using testing::input_error;

TEST(MovedKeys, NameTheirNewPlace) {
  EXPECT_EQ(moved_key("contact.beta"), "contact.peridynamics.beta");
  EXPECT_EQ(moved_key("contact.normal"), "contact.mpm.normal");
  EXPECT_EQ(moved_key("peridynamics.contact_stiffness"),
            "contact.peridynamics.repulsion.stiffness");
  EXPECT_EQ(moved_key("contact.peridynamics.beta"), std::nullopt);
  EXPECT_EQ(moved_key("contact.normals"), std::nullopt);
  EXPECT_EQ(moved_key("peridynamics.horizon_factor"), std::nullopt);
}

// The MPM's keys the old way, in the file and by --set, against the new ones.
TEST(MovedKeys, OldMpmContactKeysReadAsTheNewOnes) {
  const Case old_way = load_case(example("al-14um-810.yaml"),
                                 {parse_override("contact={normal: highest-id, friction: 0.2}"),
                                  parse_override("contact.gap_check=false")});
  const Case new_way = load_case(
      example("al-14um-810.yaml"),
      {parse_override("contact.mpm={normal: highest-id, friction: 0.2, gap_check: false}")});
  EXPECT_EQ(old_way.contact.mpm.normal, ContactNormal::HighestId);
  EXPECT_EQ(old_way.contact.mpm.friction, 0.2);
  EXPECT_FALSE(old_way.contact.mpm.gap_check);
  EXPECT_EQ(old_way.contact, new_way.contact);
}

// Peridynamics' keys the old way, the repulsion's under `peridynamics`, against the new ones.
TEST(MovedKeys, OldPeridynamicsContactKeysReadAsTheNewOnes) {
  const std::string file = example("verification/pd-quarter-impact.yaml");
  const Case old_way =
      load_case(file, {parse_override("contact={model: lennard-jones, beta: 0.004, r0: 1.2}"),
                       parse_override("peridynamics.contact_distance=1.2"),
                       parse_override("peridynamics.contact_stiffness=12")});
  const Case new_way = load_case(
      file, {parse_override("contact.peridynamics={model: lennard-jones, beta: 0.004, r0: 1.2, "
                            "repulsion: {distance: 1.2, stiffness: 12}}")});
  EXPECT_EQ(old_way.contact.peridynamics.model, ContactModel::LennardJones);
  EXPECT_EQ(old_way.contact.peridynamics.beta, 0.004);
  EXPECT_EQ(old_way.contact.peridynamics.repulsion.distance, 1.2);
  EXPECT_EQ(old_way.contact.peridynamics.repulsion.stiffness, 12.0);
  EXPECT_EQ(old_way.contact, new_way.contact);
  EXPECT_EQ(old_way.peridynamics, new_way.peridynamics);
}

// The resolved echo of examples/al-14um-810.yaml from before the split, with `old` replaced by
// `now` (a line of its contact section; it gives every contact key the old way).
std::string old_echo_with(const std::string& old, const std::string& now) {
  std::string text = coldspray::testing::read_text(case_path("resolved-before-split-mpm.yaml"));
  const std::size_t at = text.find(old);
  EXPECT_NE(at, std::string::npos) << old;
  return text.replace(at, old.size(), now);
}

// The repulsion's old keys, in a file with no contact section, make one.
TEST(MovedKeys, OldRepulsionKeysMakeTheContactSection) {
  const std::string text =
      coldspray::testing::read_text(example("verification/pd-quarter-impact.yaml")) +
      "peridynamics: {contact_stiffness: 12, horizon_factor: 3.5}\n";
  const Case c = load_case_text("pd", text);
  EXPECT_EQ(c.contact.peridynamics.repulsion.stiffness, 12.0);
  EXPECT_EQ(c.contact.peridynamics.repulsion.distance, 1.35);
  EXPECT_EQ(c.peridynamics->horizon_factor, 3.5);
}

// A --set of the old key replaces what the file gives the old way.
TEST(MovedKeys, ASetOfTheOldKeyReplacesTheFilesOldKey) {
  const Case c = load_case(case_path("resolved-before-split-mpm.yaml"),
                           {parse_override("contact.friction=0.3")});
  EXPECT_EQ(c.contact.mpm.friction, 0.3);
}

// Line 110 of the echo is "  friction: 0"; its value starts at column 13.
TEST(MovedKeys, TheSameKeyGivenBothWaysIsRefusedNamingBoth) {
  const std::string text = old_echo_with("contact:\n", "contact:\n  mpm: {friction: 0.2}\n");
  const InputError e = input_error([&] { load_case_text("echo", text); });
  EXPECT_EQ(e.where(), "echo:111:13");
  EXPECT_TRUE(contains(e.message(), "contact.mpm.friction")) << e.message();
  EXPECT_TRUE(contains(e.message(), "contact.friction")) << e.message();
}

// A bad value under an old key is reported where the file wrote it.
TEST(MovedKeys, ABadValueUnderAnOldKeyIsLocatedInTheFile) {
  const std::string text = old_echo_with("  friction: 0\n", "  friction: -1\n");
  const InputError e = input_error([&] { load_case_text("echo", text); });
  EXPECT_EQ(e.where(), "echo:110:13");
  EXPECT_TRUE(contains(e.message(), "must be >= 0")) << e.message();
}

// A run folder from before the split: its case.resolved.yaml, which its checkpoints also hold
// and a restart reads (tests/data/cases/resolved-before-split-*.yaml, written by coldspray at
// bfafd7a), reads as the case it was made from.
TEST(MovedKeys, AResolvedEchoFromBeforeTheSplitReadsAsTheSameCase) {
  const Case mpm = load_case(case_path("resolved-before-split-mpm.yaml"));
  const Case mpm_source = load_case(example("al-14um-810.yaml"));
  EXPECT_EQ(mpm.contact, mpm_source.contact);
  EXPECT_EQ(mpm.contact.mpm.normal, ContactNormal::Body);
  EXPECT_EQ(mpm.contact.mpm.normal_body, "substrate");
  const Case pd = load_case(case_path("resolved-before-split-pd.yaml"));
  const Case pd_source =
      load_case(example("verification/pd-quarter-impact.yaml"),
                {parse_override("contact.peridynamics={model: interface-bonds, softening: 300, "
                                "fracture_energy: 2 J/m^2, repulsion: {distance: 1.2}}")});
  EXPECT_EQ(pd.contact, pd_source.contact);
  EXPECT_EQ(pd.peridynamics, pd_source.peridynamics);
  EXPECT_EQ(pd.contact.peridynamics.repulsion.distance, 1.2);
}

}  // namespace
}  // namespace coldspray::case_file
