// coldspray: cold-spray particle impact simulation. Entry point: parses the command line,
// dispatches to one subcommand and maps failures to exit statuses (core/error.hpp).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/unknown_option.hpp"
#include "core/error.hpp"
#include "run/interrupt.hpp"

int main(int argc, char** argv) {
  using namespace coldspray;
  CLI::App app{"coldspray: simulate cold-spray particle impacts (MPM with direct bonding)",
               "coldspray"};
  app.set_version_flag("--version", std::string("coldspray ") + COLDSPRAY_VERSION);
  app.require_subcommand(1);
  // CLI11's own refusals (a missing value, a required option, a validator's) start "error: " as
  // every other refusal does (exit status 2), so a script or a user can tell them from output.
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return "error: " + CLI::FailureMessage::simple(a, e);
  });
  cli::add_run(app);
  cli::add_impact(app);
  cli::add_check(app);
  cli::add_materials(app);
  cli::add_material_test(app);
  cli::add_bulk_fracture(app);
  cli::add_pull_off(app);
  cli::add_sweep(app);
  cli::add_vcrit(app);
  cli::add_calibrate(app);
  cli::add_deposit(app);

  run::catch_interrupts();
  try {
    app.parse(argc, argv);
    return kExitOk;
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown option first: it often explains the error CLI11 reports (a required option
    // "missing" because it was misnamed).
    if (const auto unknown = cli::unknown_option_message(app)) {
      std::cerr << "error: " << *unknown << "\n";
      return kExitBadInput;
    }
    app.exit(e);
    return kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const RunFault& e) {
    std::cerr << "fault: " << e.what() << "\n";
    return kExitRunFault;
  } catch (const run::Interrupted& e) {
    std::cerr << e.what() << "\n";
    return 128 + e.signal();
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
