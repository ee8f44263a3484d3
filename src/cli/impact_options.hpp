// The options that shape the thesis' particle-on-cylinder case, shared by `coldspray impact`
// (one diameter and speed) and `coldspray vcrit` (many of each): registration on a subcommand
// and their translation into an ImpactSpec (setups/impact_case.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include "setups/impact_case.hpp"

namespace coldspray::cli {

// Everything but the particle's diameter and speed, as given on the command line.
// Empty --material, --geometry and --bonding take the solver's defaults: al-ptw is not one (the
// MPM needs --material), cu-jc, 3d and none for peridynamics (the PD paper's set-up).
struct ImpactCaseOptions {
  std::string solver = "mpm";
  std::string setup = "similar";  // similar | thesis (docs/impact.md, "The set-up")
  std::string material, substrate_material, resolution, grid, spacing;
  std::string geometry, symmetry = "quarter", bonding;
  std::string gc, gc_rate, eps_c, eps_c_rate, floor;
  std::string contact = "repulsive", beta;
  std::string end_time, shape_function = "gimp";  // end_time empty: the set-up's
  std::optional<int> coarsening;  // MPM: levels of the substrate's coarsened seeding; 0: uniform;
                                  // unset: the set-up's
};

// --solver, --material (required with the MPM), --substrate-material, --grid (MPM), --spacing
// (PD), --geometry, --symmetry, --contact and --beta (PD), --bonding, --Gc,
// --Gc-rate, --eps-c, --eps-c-rate, --floor, --end-time, --shape-function, --coarsening; `o` must
// outlive
// the parse. `particle_options` is called after the materials, to add the caller's options for
// the particle's size and speed there (their place in --help and in generated headers).
void add_impact_case_options(CLI::App& sub, ImpactCaseOptions& o,
                             const std::function<void()>& particle_options);

// A diameter or an impact speed given to `option`: a quantity > 0, else InputError.
double parse_diameter(const std::string& option, const std::string& text);
double parse_speed(const std::string& option, const std::string& text);

// The spec of one impact from the options, a diameter and a speed (SI); InputError names the
// option at fault. `command` is echoed in a written case's header.
setups::ImpactSpec impact_spec(const ImpactCaseOptions& o, double diameter, double speed,
                               const std::string& command);

// The energy model's defaults are the project's calibration for al-ptw on al-ptw
// (docs/validation/critical-velocity.md): for any other pair, unless --Gc and --Gc-rate are
// given, the warning to print (empty otherwise).
std::string calibration_warning(const ImpactCaseOptions& o);

std::string shell_quoted(const std::string& text);

// `source` and the subcommand's options as given, without those in `skip`: the header of a
// generated case file.
std::string command_line(const std::string& source, const CLI::App& sub,
                         std::initializer_list<std::string_view> skip);

}  // namespace coldspray::cli
