#include "setups/deposit_case.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "case/grid_domain.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "setups/case_text.hpp"

namespace coldspray::setups {

studies::Placement deposit_placement(const DepositFile& file) {
  studies::Placement placement = studies::place_particles(file.plan);
  if (placement.unplaced >= 0) {
    const std::size_t k = static_cast<std::size_t>(placement.unplaced);
    throw InputError(
        file.patch_where, "patch",
        fmt::format("particle {} of {} found no place {} um clear of the particles placed before "
                    "it in {} draws: widen the patch or the arrival_window, or spray fewer",
                    k + 1, file.plan.count, file.plan.clearance * 1e6, studies::kPlacementTries));
  }
  return placement;
}

std::vector<std::string> particle_names(int count) {
  const int digits = static_cast<int>(std::to_string(count).size());
  std::vector<std::string> names;
  for (int i = 1; i <= count; ++i) names.push_back(fmt::format("p{:0{}}", i, digits));
  return names;
}

geometry::Box substrate_box(const DepositFile& file) {
  const double half_x = 0.5 * file.plan.patch[0] + file.substrate_margin;
  const double half_y = 0.5 * file.plan.patch[1] + file.substrate_margin;
  return {case_file::Vec3(-half_x, -half_y, -file.substrate_thickness),
          case_file::Vec3(half_x, half_y, 0.0)};
}

namespace {

// The bodies: the particles in arrival order, each keyed to the file's `particles`, then the
// substrate box, coarsened below the depth kept fine for the largest particle.
void append_bodies(const DepositFile& file, const std::vector<studies::PlacedParticle>& particles,
                   double largest, GeneratedCase& g) {
  const std::vector<std::string> names = particle_names(static_cast<int>(particles.size()));
  const geometry::Box substrate = substrate_box(file);
  const double half_x = substrate.max.x(), half_y = substrate.max.y();
  auto line = [&g](const std::string& text) { g.yaml += text + "\n"; };
  line("bodies:");
  for (std::size_t i = 0; i < particles.size(); ++i) {
    stop_set_up_if_interrupted("generating the case");
    const studies::PlacedParticle& p = particles[i];
    line(fmt::format("  - name: {}   # arrives at {:.4g} ns", names[i], p.arrival * 1e9));
    line("    material: " + yaml_scalar(file.material));
    line(fmt::format("    shape: {{type: sphere, center: {}, radius: {}}}",
                     vector_um(case_file::Vec3(p.centre[0], p.centre[1], p.centre[2])),
                     um(0.5 * p.diameter)));
    line("    spacing: " + um(file.spacing));
    line(fmt::format("    velocity: [0, 0, -{} m/s]", number(p.speed)));
    line(fmt::format("    temperature: {} K", number(file.temperature)));
    for (const char* key : {"material", "shape", "velocity", "temperature"})
      g.origins.push_back({fmt::format("bodies.{}.{}", names[i], key), file.particles_where});
    // The spacing is the grid's, as the substrate's is.
    g.origins.push_back({fmt::format("bodies.{}.spacing", names[i]), file.grid_where});
  }
  line("  - name: substrate");
  line("    material: " + yaml_scalar(file.substrate_material));
  line(fmt::format("    shape: {{type: box, min: {}, max: {}}}", vector_um(substrate.min),
                   vector_um(substrate.max)));
  line("    spacing: " + um(file.spacing));
  line(fmt::format("    temperature: {} K", number(file.substrate_temperature)));
  line("    absorbing: [bottom, side]   # a semi-infinite substrate (thesis §3.5.5)");
  g.origins.push_back({"bodies.substrate.shape", file.patch_where});
  g.origins.push_back({"bodies.substrate.spacing", file.grid_where});
  if (file.coarsening > 0) {
    // Fine under the whole patch down to the depth `coldspray impact --coarsening` keeps fine
    // below one impact (impact_case.hpp), for the largest particle.
    const double depth = std::min(kCoarseningFineDepth * largest, file.substrate_thickness);
    line(fmt::format(
        "    coarsening: {{levels: {}, fine: {{type: box, min: {}, max: {}}}}}   # coarser "
        "points below the impacts (docs/mpm.md)",
        file.coarsening, vector_um(case_file::Vec3(-half_x, -half_y, -depth)),
        vector_um(case_file::Vec3(half_x, half_y, 0.0))));
    g.origins.push_back({"bodies.substrate.coarsening", file.substrate_where});
  }
}

}  // namespace

GeneratedCase deposit_case(const DepositFile& file, const studies::Placement& placement) {
  const std::vector<studies::PlacedParticle>& particles = placement.particles;
  const geometry::Box substrate = substrate_box(file);
  const double half_x = substrate.max.x(), half_y = substrate.max.y();
  double last_arrival = 0.0, largest = 0.0, highest = 0.0;
  for (const studies::PlacedParticle& p : particles) {
    last_arrival = std::max(last_arrival, p.arrival);
    largest = std::max(largest, p.diameter);
    highest = std::max(highest, p.centre[2] + 0.5 * p.diameter);
  }
  // The grid: the substrate and kGridMarginMinCells cells around it, and up to the highest
  // particle's top and a diameter above it, for rebounds and jets (what leaves it leaves the
  // run, mpm/departures.hpp). The solver's own margin, half the bodies' extent each way, would
  // put four times the nodes into the empty space of a tall deposit.
  const double cells = case_file::kGridMarginMinCells * file.cell_size;
  const case_file::Vec3 grid_min(-half_x - cells, -half_y - cells,
                                 -file.substrate_thickness - cells);
  const case_file::Vec3 grid_max(half_x + cells, half_y + cells,
                                 highest + std::max(cells, largest));

  GeneratedCase g;
  g.name = file.name;
  auto line = [&g](const std::string& text) { g.yaml += text + "\n"; };
  auto comment = [&g](std::string_view text) { append_comment(g.yaml, text); };
  line("# Generated by: coldspray deposit " + one_line(file.path));
  comment(fmt::format(
      "{} particles of {} placed by seed {} (docs/deposit.md, \"Placement\"): each starts its "
      "speed times its arrival time above the substrate's top face z = 0, the first touching it "
      "at t = 0; centres over a {} x {} patch; the {} substrate box spans the patch and {} "
      "beyond it on each side, {} deep. The run ends {} ns after the last arrival.",
      particles.size(), file.material, file.plan.seed, um(file.plan.patch[0]),
      um(file.plan.patch[1]), file.substrate_material, um(file.substrate_margin),
      um(file.substrate_thickness), number(file.settle_time * 1e9)));
  line("name: " + g.name);
  line("description: " +
       yaml_scalar(file.description.empty()
                       ? fmt::format("{} {} particles on a {} substrate, 3d", particles.size(),
                                     file.material, file.substrate_material)
                       : file.description));
  append_bodies(file, particles, largest, g);
  line("grid:");
  line("  cell_size: " + um(file.cell_size));
  line("  min: " + vector_um(grid_min));
  line("  max: " + vector_um(grid_max));
  line("solver:");
  line("  geometry: 3d");
  line("  shape_function: gimp");
  line(fmt::format("  end_time: {} ns", number((last_arrival + file.settle_time) * 1e9)));
  line("contact:");
  line("  mpm:");
  if (file.contact_normal == "substrate") {
    line("    normal: body:substrate   # at particle-substrate pairs, as the calibration");
    line("    other_pairs_normal: average-gradient   # between particles");
  } else {
    line("    normal: " + file.contact_normal +
         "   # the bodies in arrival order, the substrate last (thesis §5.2.3)");
  }
  line("bonding:");
  line("  model: " + file.bonding);
  line("metrics:");
  line(fmt::format("  verdict_window: {} ns", number(file.verdict_window * 1e9)));
  line("output:");
  line("  history_interval: 0.5 ns");
  line("  snapshot_interval: 10 ns");
  g.origins.push_back({"grid.cell_size", file.grid_where});
  g.origins.push_back({"solver.end_time", file.file_where});
  return g;
}

}  // namespace coldspray::setups
