// Issue 52, item 1, end to end: `coldspray impact --Gc 1e12J/m^2` wrote the case text
// "critical_energy: 1e+12 J/m^2", which was read back as 1 J/m^2, and a run used G_c = 1 J/m^2.
// Numbers are read as written on the command line, in --set and in case files, or refused with
// status 2 naming the option or FILE:LINE:COLUMN and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "case/load.hpp"
#include "core/units.hpp"
#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;
const std::string kImpact = "impact --material al-ptw --diameter 22um --velocity 790m/s";

TEST(NumberSyntax, ImpactWritesTheEnergyItWasGiven) {
  const std::string dir = make_temp_dir("numbers");
  const auto r = run_coldspray(kImpact +
                                   " --bonding energy --Gc 1e12J/m^2 --Gc-rate 2.8e+5J/m^2/us "
                                   "--eps-c-rate '8E+08 1/s' --end-time 6e+1ns "
                                   "--write-case case.yaml",
                               dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path file = fs::path(dir) / "case.yaml";
  // The text that was misread: the exponent's '+' is what fmt and printf write.
  EXPECT_NE(read_text(file).find("critical_energy: 1e+12 J/m^2"), std::string::npos)
      << read_text(file);
  const case_file::Case c = case_file::load_case(file.string());
  EXPECT_EQ(c.bonding.critical_energy, 1e12);
  EXPECT_EQ(c.bonding.critical_energy_rate, 2.8e11);
  EXPECT_EQ(c.bonding.critical_strain_rate, 8e8);
  EXPECT_EQ(c.solver.end_time, 60e-9);
  const auto check = run_coldspray("check case.yaml", dir);
  EXPECT_EQ(check.status, 0) << check.output;
}

TEST(NumberSyntax, SetTakesEveryForm) {
  const std::string dir = make_temp_dir("numbers");
  const auto r = run_coldspray(kImpact +
                                   " --set 'bonding.critical_energy=1e+3 J/m^2' "
                                   "--set 'bonding.critical_energy_rate=+1.5E+005 J/m^2/us' "
                                   "--set 'solver.cfl=.25' --write-case case.yaml",
                               dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const case_file::Case c = case_file::load_case((fs::path(dir) / "case.yaml").string());
  EXPECT_EQ(c.bonding.critical_energy, 1e3);
  EXPECT_EQ(c.bonding.critical_energy_rate, 1.5e11);
  EXPECT_EQ(c.solver.cfl, 0.25);
}

// Refused with status 2, the option named, and no case written.
TEST(NumberSyntax, MalformedOptionValuesAreRefused) {
  const std::pair<const char*, const char*> cases[] = {
      {"--Gc 1e+J/m^2", "--Gc: '1e+J/m^2' is not a number"},
      {"--Gc '1e 3 J/m^2'", "--Gc: '1e 3 J/m^2' is not a number"},
      {"--Gc 1e3.5J/m^2", "--Gc: '1e3.5J/m^2' is not a number"},
      {"--Gc 0x10J/m^2", "hexadecimal is not accepted"},
      {"--Gc 1e+400J/m^2", "--Gc: '1e+400J/m^2': value out of range"},
      {"--Gc-rate 1e-400J/m^2/us", "value out of range"},
      {"--diameter +-22um", "--diameter: '+-22um' is not a number"},
      {"--set 'bonding.critical_energy=1e++3 J/m^2'",
       "--set bonding.critical_energy: key 'bonding.critical_energy': '1e++3 J/m^2' is not a "
       "number"},
  };
  for (const auto& [options, message] : cases) {
    SCOPED_TRACE(options);
    const std::string dir = make_temp_dir("numbers");
    std::string args = kImpact + " --write-case case.yaml " + options;
    if (std::string(options).starts_with("--diameter"))
      args = std::string("impact --material al-ptw --velocity 790m/s --write-case case.yaml ") +
             options;
    const auto r = run_coldspray(args, dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(has(r, message)) << r.output;
    EXPECT_FALSE(fs::exists(fs::path(dir) / "case.yaml"));
  }
}

TEST(NumberSyntax, MalformedNumbersInACaseFileNameTheLineAndKey) {
  const std::string dir = make_temp_dir("numbers");
  std::ofstream(fs::path(dir) / "bad.yaml") << "name: bad\n"
                                               "bodies:\n"
                                               "  - name: particle\n"
                                               "    material: al-ptw\n"
                                               "    shape: {type: sphere, center: [0, 0, 7 um], "
                                               "radius: 7 um}\n"
                                               "    spacing: 1.75e-1.5 um\n"
                                               "grid:\n"
                                               "  cell_size: 0.7 um\n"
                                               "solver:\n"
                                               "  end_time: 80 ns\n";
  const auto r = run_coldspray("check bad.yaml", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(
      has(r, "bad.yaml:6:14: key 'bodies.particle.spacing': '1.75e-1.5 um' is not a number"))
      << r.output;
}

}  // namespace
}  // namespace coldspray::testing
