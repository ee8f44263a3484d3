// Bond families (run/bond_family.hpp) against independent runs: members that share the unbonded
// trajectory and leave it at different steps, or never, write exactly what run_case writes for
// them, file for file and bit for bit, but for the wall time. The small bonding impact
// (examples/verification/bonding-impact.yaml, 10 ns) with G_c = 1 and 1.5 J/m^2 bonds at first
// contact, 50 J/m^2 some steps later, 1000 and 3000 J/m^2 never bond a node (their particles
// rebound). The verdict's window, 10 ns, holds the impact at 10 ns, so every member with bonded
// area is undecided then and extended to 20 ns, on its branch or on the trunk (1000 J/m^2), while
// 3000 J/m^2, with none, ends on the trunk at 10 ns. A member whose folder cannot be written fails
// alone.
#include "run/bond_family.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "read_text.hpp"
#include "run/run.hpp"
#include "temp_dir.hpp"

namespace coldspray::run {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

case_file::Case bonding_impact(const std::string& critical_energy,
                               const std::string& velocity = "-800 m/s") {
  return case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/bonding-impact.yaml",
      {{"bonding.critical_energy", critical_energy},
       {"bodies.particle.velocity", "[0, 0, " + velocity + "]"},
       {"solver.end_time", "10 ns"},
       {"output.snapshot_interval", "5 ns"},
       {"metrics.verdict_window", "10 ns"}});
}

// Every result file under the folder, by path relative to it: not the checkpoints, which a
// solo run writes and a family's members do not (docs/reliability.md).
std::set<std::string> files_under(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    // Not results: a run's id (random) and the lock of a folder run_case held.
    const std::string name = entry.path().filename().string();
    if (name == "run_id.txt" || name == ".coldspray.lock") continue;
    if (entry.is_regular_file() && entry.path().parent_path().filename() != "checkpoints")
      names.insert(fs::relative(entry.path(), folder).string());
  }
  return names;
}

nlohmann::json summary_without_timing(const fs::path& folder) {
  nlohmann::json j = nlohmann::json::parse(read_text(folder / "summary.json"));
  for (const char* key : {"wall_seconds", "particle_steps_per_second", "shared_steps"})
    j.erase(key);
  return j;
}

TEST(BondFamily, MembersWriteWhatTheirOwnRunsWrite) {
  const std::vector<std::string> energies = {"1 J/m^2", "1.5 J/m^2", "50 J/m^2", "1000 J/m^2",
                                             "3000 J/m^2"};
  const fs::path dir = testing::make_temp_dir("bond-family");
  std::vector<FamilyMember> members;
  for (std::size_t i = 0; i < energies.size(); ++i) {
    const case_file::Case c = bonding_impact(energies[i]);
    RunOptions solo;
    solo.out_dir = dir / "solo" / std::to_string(i);
    solo.progress = false;
    run_case(c, solo);
    members.push_back({c, dir / "family" / std::to_string(i)});
  }
  std::ofstream(dir / "not-a-folder") << "a file where the last member's folder would go\n";
  members.push_back({bonding_impact("1000 J/m^2"), dir / "not-a-folder" / "member"});

  // Branches run after the trunk has returned, as a scheduler may run them.
  std::vector<std::function<void()>> branches;
  std::vector<int> finished(members.size(), 0), failed(members.size(), 0);
  FamilyHooks hooks;
  hooks.spawn = [&](std::function<void()> branch) { branches.push_back(std::move(branch)); };
  hooks.finished = [&](std::size_t member, std::exception_ptr failure) {
    ++finished[member];
    failed[member] += failure != nullptr;
  };
  run_bond_family(members, hooks);
  EXPECT_EQ(branches.size(), 3u);  // G_c = 1, 1.5 and 50 J/m^2 bond; 1000 and 3000 never do
  for (auto& branch : branches) branch();
  for (std::size_t i = 0; i < members.size(); ++i) {
    EXPECT_EQ(finished[i], 1) << i;
    EXPECT_EQ(failed[i], i == energies.size() ? 1 : 0) << i;
  }

  std::vector<long> shared(energies.size()), steps(energies.size());
  std::vector<int> extensions(energies.size());
  std::vector<std::string> outcomes(energies.size());
  for (std::size_t i = 0; i < energies.size(); ++i) {
    const fs::path solo = dir / "solo" / std::to_string(i), family = members[i].out_dir;
    const std::set<std::string> names = files_under(solo);
    EXPECT_EQ(files_under(family), names) << energies[i];
    for (const std::string& name : names) {
      if (name == "summary.json") continue;
      EXPECT_TRUE(read_text(solo / name) == read_text(family / name))
          << energies[i] << ": " << name;
    }
    EXPECT_EQ(summary_without_timing(solo), summary_without_timing(family)) << energies[i];
    const nlohmann::json s = nlohmann::json::parse(read_text(family / "summary.json"));
    shared[i] = s["shared_steps"].get<long>();
    steps[i] = s["steps"].get<long>();
    extensions[i] = s["system"]["extensions"].get<int>();
    outcomes[i] = s["system"]["outcome"].get<std::string>();
  }
  for (std::size_t i = 0; i < energies.size(); ++i)
    std::printf("G_c = %s: %ld of %ld steps shared with the trunk; %s after %d extensions\n",
                energies[i].c_str(), shared[i], steps[i], outcomes[i].c_str(), extensions[i]);
  EXPECT_LE(shared[0], shared[1]);  // 1 and 1.5 J/m^2 leave first,
  EXPECT_LT(shared[1], shared[2]);  // 50 J/m^2 later,
  EXPECT_LT(shared[2], steps[2]);
  EXPECT_EQ(shared[3], steps[3]);  // the others never
  EXPECT_EQ(shared[4], steps[4]);
  // Every member is still in its impact at 10 ns and ends at 20 ns: no bond having formed by then
  // does not yet say it never will.
  EXPECT_EQ(extensions, (std::vector<int>{1, 1, 1, 1, 1}));
  EXPECT_EQ(steps[4], steps[3]);
  EXPECT_EQ(outcomes,
            (std::vector<std::string>{"bonded", "bonded", "bonded", "rebounded", "rebounded"}));
}

TEST(BondFamily, OnlyTheBondingParametersMayDiffer) {
  const case_file::Case a = bonding_impact("50 J/m^2");
  EXPECT_TRUE(same_but_bonding(a, bonding_impact("3000 J/m^2")));
  EXPECT_FALSE(same_but_bonding(a, bonding_impact("50 J/m^2", "-700 m/s")));
  case_file::Case unbonded = a;
  unbonded.bonding.model = case_file::BondingModel::None;
  EXPECT_FALSE(same_but_bonding(unbonded, unbonded));
  FamilyHooks hooks;
  hooks.spawn = [](std::function<void()>) {};
  hooks.finished = [](std::size_t, std::exception_ptr) {};
  EXPECT_THROW(
      run_bond_family({{a, "unused-a"}, {bonding_impact("50 J/m^2", "-700 m/s"), "b"}}, hooks),
      std::invalid_argument);
}

}  // namespace
}  // namespace coldspray::run
