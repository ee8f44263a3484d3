// The impact measures of a body (thesis §5.2.2 and Chapter 4), over its points on the grid; the
// jetted fraction also counts those that have left it. The bonded verdict, which reads them over
// the run's last window, is metrics/verdict.hpp's.
#pragma once

#include <cstddef>
#include <vector>

#include "bodies/bodies.hpp"

namespace coldspray::metrics {

struct ImpactMeasures {
  // Restitution ratio: -v_z / v0_z of the mass-averaged velocity; > 0 moving away. NaN for a
  // body that started at rest in z.
  double cor = 0.0;
  // Mass-averaged z velocity of the points no faster than metrics.rest_speed_limit (thesis
  // §5.2.2's v_rest, whose 60 m/s filter leaves jetted material out), m/s; NaN if none is.
  double v_rest = 0.0;
  double abp = 0.0;   // mean D_bond over the surface points that have touched another body
  double pbcp = 0.0;  // % of contacted mass with D_bond >= 1 (eq 5.1), see docs/bonding.md
  double plastic_energy_density = 0.0;  // plastic work over the reference volume (eq 4.15), J/m^3
  // Mass fraction of jetted points: faster than rest_speed_limit relative to the body's mean
  // z velocity and moving away from the body's axis (the vertical through its centroid),
  // counting the points that have left the grid (jets thrown off it) as jetted, of the body's
  // initial mass.
  double jetted_fraction = 0.0;
  // Deepest sinking of the points that started in the body's top layer, m (the crater of a
  // substrate).
  double crater_depth = 0.0;
  // Diameter across the axis of the body's points that are not jetted, over that at t = 0; of a
  // body that moved, only its splat's points (bodies/splat_piece.hpp), not drops it shed. NaN
  // where not measured (SplatExtent::Skipped).
  double flattening_ratio = 0.0;
  // The largest penetration since first contact over the body's size (bodies/penetration.hpp):
  // bonding's activation. NaN for a body that started at rest.
  double penetration = 0.0;
  double penetration_peak_time = 0.0;  // when the compression ended, s; NaN: not yet
  double contact_area = 0.0;           // surface area of the points that touched another body, m^2
  double bonded_area = 0.0;            // of those that keep a bond (bodies::Points::bonded_to), m^2
  // bonded_area by the body the bond holds to, indexed by body (0 for the body itself), m^2.
  std::vector<double> bonded_area_with;
  // Eq 5.1's masses, of the whole body (symmetry planes counted): with D_bond > 0 and >= 1, kg.
  // Summed over bodies they give the system's PBCP (system_pbcp).
  double contacted_mass = 0.0;
  double bonded_mass = 0.0;
  bool moving = false;  // started with a z velocity: cor and the verdict apply
};

// Whether impact_measures finds the splat's extent (the flattening ratio), which takes a search
// for the piece of the body that hangs together: once for a summary, not for every history row.
enum class SplatExtent { Measured, Skipped };

ImpactMeasures impact_measures(const bodies::Bodies& s, std::size_t body, SplatExtent extent);

// The PBCP of eq 5.1 over all the bodies' contacted points, as thesis Table 5.5 reports it for a
// multi-particle system: 100 sum bonded_mass / sum contacted_mass, %; 0 where nothing touched.
double system_pbcp(const std::vector<ImpactMeasures>& bodies);

// What the verdict follows of a body, from one pass over its points, as ImpactMeasures counts
// it: the mass and z momentum of all its points and of those at rest (v_rest = rest_momentum_z /
// rest_mass), and its bonded area.
struct RestAndBond {
  double mass = 0.0;             // kg
  double momentum_z = 0.0;       // kg m/s
  double rest_mass = 0.0;        // of the points no faster than metrics.rest_speed_limit, kg
  double rest_momentum_z = 0.0;  // kg m/s
  double bonded_area = 0.0;      // m^2
};

RestAndBond rest_and_bond(const bodies::Bodies& s, std::size_t body);

// The surface area of the body's points that another body acts on now (bodies::Points::touching),
// for the whole body (symmetry planes counted), m^2.
double touching_area(const bodies::Bodies& s, std::size_t body);

}  // namespace coldspray::metrics
