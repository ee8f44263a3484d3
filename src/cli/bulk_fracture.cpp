// `coldspray bulk-fracture`: the numerical bulk-fracture test of the PD paper's contact model 2
// (pd/laws/bulk_fracture.hpp) for one material and spacing, and the fit of eq 24 to it: the
// constants an impact with `contact.peridynamics.model: interface-bonds` uses unless its case gives
// them.
#include "pd/laws/bulk_fracture.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/quantity_option.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "studies/bulk_fracture_fit.hpp"

namespace coldspray::cli {

void add_bulk_fracture(CLI::App& app) {
  struct Options {
    std::string material, spacing = "1.2 um", fracture_energy, out;
    double horizon_factor = 3.0;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand(
      "bulk-fracture",
      "Contact model 2's bulk-fracture test and the fit of its force-stretch law (PD paper Fig 1)");
  sub->add_option("--material", opt->material, "Built-in NAME or CASE.yaml:NAME")->required();
  sub->add_option("--spacing", opt->spacing, "Point spacing, e.g. 1.2um")->capture_default_str();
  sub->add_option("--horizon-factor", opt->horizon_factor, "Horizon in spacings")
      ->capture_default_str();
  sub->add_option("--fracture-energy", opt->fracture_energy,
                  "G_c, e.g. 3.65J/m^2 (default: twice the material's surface energy)");
  sub->add_option("--out", opt->out, "Output folder (bulk_fracture.csv, fit.json)")
      ->required()
      ->check(given_path());
  sub->callback([opt] {
    const materials::Material material = case_file::resolve_material(opt->material, "--material");
    const double h = parse_option_quantity("--spacing", opt->spacing, units::kLength);
    if (!(h > 0.0)) throw InputError("--spacing", "", "must be positive");
    if (!(opt->horizon_factor > 2.0 && opt->horizon_factor < 6.0))
      throw InputError("--horizon-factor", "", "must be in (2, 6), as peridynamics.horizon_factor");
    double G_c = 2.0 * material.surface_energy;
    if (!opt->fracture_energy.empty())
      G_c = parse_option_quantity("--fracture-energy", opt->fracture_energy, units::kEnergyPerArea);
    if (!(G_c > 0.0))
      throw InputError("--fracture-energy", "",
                       fmt::format("must be positive (material '{}' has no surface_energy to "
                                   "take it from)",
                                   material.name));
    io::make_output_folder(opt->out);

    const double K = material.elastic.bulk_modulus;
    const double delta = opt->horizon_factor * h;
    const double c = 18.0 * K / (std::numbers::pi * std::pow(delta, 4));  // N/m^6
    const double s_c = pd::critical_stretch(G_c, K, delta);               // eq 23
    const pd::ForceStretchCurve curve =
        pd::bulk_fracture_curve(opt->horizon_factor, pd::kBulkFractureSamples);
    const pd::InterfaceBondLaw law = pd::scaled_law(pd::fit_interface_law(curve), s_c);

    const std::filesystem::path folder(opt->out);
    io::write_atomically(folder / "bulk_fracture.csv", [&](std::ostream& out) {
      out << "stretch,bulk_force_density,fitted_force_density\n";
      for (std::size_t n = 0; n < curve.stretch.size(); ++n) {
        const double s = curve.stretch[n] * s_c;
        out << fmt::format("{:.9g},{:.9g},{:.9g}\n", s, c * s_c * curve.force[n],
                           c * pd::envelope_per_micromodulus(law, s));
      }
    });
    studies::write_bulk_fracture_fit(
        folder / "fit.json",
        {material.name, h, delta, K, c, G_c, s_c, law.yield_stretch, law.softening,
         law.break_stretch(), pd::work_of_fracture(curve) * s_c * s_c, pd::interface_work(law)});
    std::cout << fmt::format(
        "{} at {:.4g} um spacing, horizon {:.4g} um: G_c {:.4g} J/m^2, critical stretch s_c "
        "{:.5g} (eq 23)\nfitted (eq 24): yield stretch s_y {:.5g}, softening m {:.5g}, breaks at "
        "stretch {:.5g}\nwrote {} and {}\n",
        material.name, h * 1e6, delta * 1e6, G_c, s_c, law.yield_stretch, law.softening,
        law.break_stretch(), (folder / "bulk_fracture.csv").string(),
        (folder / "fit.json").string());
  });
}

}  // namespace coldspray::cli
