// What a pull-off test reads of an impacted state (docs/pull-off.md): the areas it divides its
// peak force by, the planes the model was cut at, and, with the MPM's debonding law, each bonded
// point's strength (the map of where the bond is strong). Each solver fills in its own bonded
// area and points (mpm/answers.hpp, pd/answers.hpp); run/interface_areas.hpp the rest.
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace coldspray::metrics {

// A bonded point of the pulled body: where it is and what its bond carries
// (bonding/cohesive_law.hpp).
struct InterfacePoint {
  std::array<double, 3> position{};  // m
  double radius = 0.0;               // from the body's axis (its centroid's vertical), m
  double area = 0.0;                 // m^2
  double bond = 0.0;                 // D_bond
  double strength = 0.0;             // sigma_c min(D_bond, 1) (1 - damage), Pa
  double damage = 0.0;
  double critical_opening = 0.0;  // delta_c = 2 G_c / sigma_c, m
};

struct InterfaceAreas {
  // The bonded area: the MPM's, of the body's points keeping a bond (bonded_to); peridynamics',
  // of its points another body acts on. m^2.
  double bonded = 0.0;
  double projected = 0.0;  // pi d^2 / 4, d the footprint's diameter (the flattening ratio's), m^2
  // The symmetry planes the body was cut at (x, y), and whether the model is r-z.
  std::array<std::optional<double>, 2> mirror_plane{};
  bool axisymmetric = false;
  std::vector<InterfacePoint> points;  // MPM with a debonding law; else empty
};

}  // namespace coldspray::metrics
