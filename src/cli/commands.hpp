// The `coldspray` subcommands, one file each. Each adds itself to the app; its callback throws
// InputError (exit 2) or RunFault (exit 3), which main() turns into a message and a status.
#pragma once

#include <CLI/CLI.hpp>

namespace coldspray::cli {

void add_run(CLI::App& app);
void add_check(CLI::App& app);
void add_materials(CLI::App& app);
void add_material_test(CLI::App& app);
void add_bulk_fracture(CLI::App& app);
void add_pull_off(CLI::App& app);
void add_sweep(CLI::App& app);
void add_impact(CLI::App& app);
void add_vcrit(CLI::App& app);
void add_calibrate(CLI::App& app);
void add_deposit(CLI::App& app);

}  // namespace coldspray::cli
