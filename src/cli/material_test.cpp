// `coldspray material-test`: drive one material point along a homogeneous loading path through
// the solvers' stress update and write the response as CSV (material_test/loading.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <vector>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/quantity_option.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "material_test/loading.hpp"

namespace coldspray::cli {

void add_material_test(CLI::App& app) {
  struct Options {
    std::string material, mode = "uniaxial-strain", strain_rate, final_strain,
                          temperature = "298 K", out;
    bool isothermal = false;
    int steps = 2000;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand("material-test",
                                 "Drive one material point through a loading path; write CSV");
  sub->add_option("--material", opt->material, "Built-in NAME or CASE.yaml:NAME")->required();
  sub->add_option("--mode", opt->mode, "uniaxial-strain | uniaxial-stress | simple-shear")
      ->capture_default_str();
  sub->add_option("--strain-rate", opt->strain_rate, "Driving strain rate, e.g. '1e7 1/s'")
      ->required();
  sub->add_option("--final-strain", opt->final_strain,
                  "Final log strain (gamma in simple shear); negative is compression")
      ->required();
  sub->add_option("--temperature", opt->temperature, "Initial temperature, e.g. '298 K'")
      ->capture_default_str();
  sub->add_flag("--isothermal", opt->isothermal, "No adiabatic heating");
  sub->add_option("--steps", opt->steps, "Number of steps")->capture_default_str();
  sub->add_option("--out", opt->out, "Output CSV file")->required()->check(given_path());
  sub->callback([opt] {
    material_test::Loading loading;
    loading.mode = material_test::parse_mode(opt->mode);
    loading.strain_rate = parse_option_quantity("--strain-rate", opt->strain_rate, units::kRate);
    loading.final_strain =
        parse_option_quantity("--final-strain", opt->final_strain, units::kDimensionless);
    loading.temperature =
        parse_option_quantity("--temperature", opt->temperature, units::kTemperature);
    loading.isothermal = opt->isothermal;
    loading.steps = opt->steps;
    const materials::Material material = case_file::resolve_material(opt->material, "--material");
    io::require_writable(opt->out, "--out");  // before the work, not after it

    std::vector<material_test::Sample> samples;
    // Clamped: drive() refuses a count beyond kMaxSteps, after this reserve.
    samples.reserve(static_cast<std::size_t>(std::clamp(opt->steps, 0, material_test::kMaxSteps)) +
                    1);
    auto write_samples = [&] {
      io::write_atomically(opt->out, [&](std::ostream& out) {
        material_test::write_csv_header(out);
        for (const auto& s : samples) material_test::write_csv_row(out, s);
      });
    };
    try {
      material_test::drive(material, loading,
                           [&](const material_test::Sample& s) { samples.push_back(s); });
    } catch (const RunFault& fault) {
      // Keep what was computed up to the fault: the rows before it are valid.
      if (!samples.empty()) write_samples();
      throw RunFault(fmt::format("{}; {} rows before the fault written to {}", fault.what(),
                                 samples.size(), opt->out));
    }
    write_samples();
    const auto& last = samples.back();
    std::cout << fmt::format(
        "{} {}: strain {:.4g}, eqps {:.4g}, eqps rate {:.4g} 1/s, T {:.1f} K, flow stress "
        "{:.2f} MPa, von Mises {:.2f} MPa, pressure {:.2f} MPa\nwrote {} ({} rows)\n",
        opt->material, opt->mode, last.strain, last.eqps, last.eqps_rate, last.temperature,
        last.flow_stress * 1e-6, last.von_mises * 1e-6, last.pressure * 1e-6, opt->out,
        samples.size());
  });
}

}  // namespace coldspray::cli
