// Small cases for the bodies/ tests: bodies of an elastic Al (2700 kg/m^3, K 66.4 GPa, G 26 GPa,
// so c_p = sqrt((K + 4G/3) / rho) = 6118.18 m/s and c_s = sqrt(G / rho) = 3103.16 m/s) on
// lattices of 0.5 um, where a point of a 3D lattice weighs 2700 x (0.5 um)^3 = 3.375e-16 kg.
#pragma once

#include <string>

#include "bodies/bodies.hpp"
#include "bodies/seed_bodies.hpp"
#include "case/load.hpp"

namespace coldspray::bodies::testing {

inline constexpr double kPointMass = 3.375e-16;  // kg, 2700 kg/m^3 x (0.5 um)^3
inline constexpr double kPWave = 6118.17773;     // m/s
inline constexpr double kSWave = 3103.16445;     // m/s

// The case of the `bodies:` items given (YAML, indented by two), on a 1 um grid; `more` adds
// top-level sections (a `solver:` replaces the default one).
inline case_file::Case elastic_case(const std::string& bodies, const std::string& more = "") {
  const std::string solver =
      more.find("solver:") == std::string::npos ? "solver:\n  end_time: 1 ns\n" : "";
  return case_file::load_case_text("bodies-test",
                                   "name: bodies-test\n"
                                   "materials:\n"
                                   "  elastic-al:\n"
                                   "    density: 2700 kg/m^3\n"
                                   "    elastic: {shear_modulus: 26 GPa, "
                                   "bulk_modulus: 66.4 GPa}\n"
                                   "    strength: {model: elastic}\n"
                                   "    eos: {model: linear}\n"
                                   "    melt: {model: constant, temperature: 933 K}\n"
                                   "    specific_heat: 896 J/kg/K\n"
                                   "bodies:\n" +
                                       bodies + "grid:\n  cell_size: 1 um\n" + solver + more);
}

// The `bodies:` item of a box of elastic-al on a 0.5 um lattice between the corners `min` and
// `max` (YAML vectors with units), followed by `more` (keys indented by four).
inline std::string box(const std::string& name, const std::string& min, const std::string& max,
                       const std::string& more = "") {
  return "  - name: " + name + "\n    material: elastic-al\n    shape: {type: box, min: " + min +
         ", max: " + max + "}\n    spacing: 0.5 um\n" + more;
}

// The case's bodies seeded and laid out, as a solver without symmetry planes does.
inline Bodies laid_out(const case_file::Case& c) {
  Bodies s;
  lay_out_bodies(c, seed_bodies(c), s);
  return s;
}

}  // namespace coldspray::bodies::testing
