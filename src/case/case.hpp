// A parsed, validated case: plain structs, SI values, defaults filled in.
// The YAML schema that fills these is described once in case/case_schema.hpp and serves parsing
// and the resolved echo (case.resolved.yaml) alike; docs/input-reference.md documents it.
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.hpp"
#include "materials/artificial_viscosity.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file {

using Vec3 = Eigen::Vector3d;

// Faces of a body that absorbing or fixed conditions apply to.
enum class BodyFace { Bottom, Side, Top };

// Coarser points away from where the body deforms (docs/mpm.md, "Coarsened seeding"): the
// lattice's cubes of 2, 4, ... 2^levels sites a side inside the body, off its surface and away
// from the box around `fine`, become one point each. MPM only.
struct Coarsening {
  int levels = 1;
  geometry::Shape fine;

  friend bool operator==(const Coarsening&, const Coarsening&) = default;
};

struct Body {
  std::string name;
  std::string material;  // a key of Case::materials
  geometry::Shape shape;
  double spacing = 0.0;  // lattice spacing of the seeded points, m
  Vec3 velocity = Vec3::Zero();
  double temperature = 298.0;       // K
  std::vector<BodyFace> absorbing;  // Lysmer-Kuhlemeyer dashpots (thesis §3.5.5)
  std::vector<BodyFace> fixed;      // zero velocity
  // Zero velocity along the face's normal: z on the bottom and top, x and y on the side (the PD
  // paper's side condition). Peridynamics only; the MPM holds grid faces (grid.faces).
  std::vector<BodyFace> roller;
  std::optional<Coarsening> coarsening;

  friend bool operator==(const Body&, const Body&) = default;
};

enum class FaceCondition { Free, Fixed, Roller };
enum class GridFace { XMin, XMax, YMin, YMax, ZMin, ZMax };

struct Grid {
  double cell_size = 0.0;   // m
  std::optional<Vec3> min;  // default: bodies' bounding box plus margin (issue 3)
  std::optional<Vec3> max;
  std::map<GridFace, FaceCondition> faces;  // all six once read; free unless set

  friend bool operator==(const Grid&, const Grid&) = default;
};

enum class Method { Mpm, Peridynamics };
enum class Geometry { ThreeD, Axisymmetric };
enum class ShapeFunction { Linear, Gimp };

using materials::ArtificialViscosity;

// The default time-step fraction of peridynamics: under half of the stable step measured on the
// undeformed lattice, about 2.6 (docs/pd.md, "Time step"); the MPM's is Solver::cfl's.
inline constexpr double kPeridynamicsCfl = 1.2;
// The largest cfl a case may give: the MPM's bound is 1, peridynamics' about 2.6.
inline constexpr double kMaxCfl = 3.0;
inline constexpr double kMaxMpmCfl = 1.0;

struct Solver {
  Method method = Method::Mpm;
  Geometry geometry = Geometry::ThreeD;
  ShapeFunction shape_function = ShapeFunction::Gimp;
  double end_time = 0.0;           // s
  double cfl = 0.3;                // dt = cfl h / max(c + |v|) (PD: pd/stepper.hpp)
  std::optional<double> dt_scale;  // alternative: fraction of the critical step (thesis §5.1.4)
  ArtificialViscosity artificial_viscosity;
  // Fourier heat conduction between points, with the materials' thermal_conductivity
  // (docs/mpm.md); off, every point heats adiabatically (thesis §3.5.3).
  bool heat_conduction = false;

  friend bool operator==(const Solver&, const Solver&) = default;
};

enum class ContactNormal { MaxGradient, Body, HighestId, AverageGradient };

// The grid contact of the MPM (thesis §3.3, docs/mpm.md "Contact"): the normal's rule at a node
// two bodies share, Coulomb friction and the surface-gap check. (`contact.mpm` in a case file.)
struct MpmContact {
  ContactNormal normal = ContactNormal::MaxGradient;
  std::string normal_body;  // with ContactNormal::Body
  // With ContactNormal::Body, the rule at pairs of other bodies (not Body): the thesis' MVG, or
  // for many particles on a substrate the average gradient between particles.
  ContactNormal other_pairs_normal = ContactNormal::MaxGradient;
  double friction = 0.0;  // Coulomb coefficient; 0 = frictionless
  // Also require the bodies' surfaces, from their points' extents, to meet at the node.
  bool gap_check = true;

  friend bool operator==(const MpmContact&, const MpmContact&) = default;
};

// The force law between points of different bodies in peridynamics (docs/pd.md, "Contact"): the
// short-range repulsion, the PD paper's contact model 1, a Lennard-Jones-type potential
// (eqs 15-22), or its model 2, interface bonds with the bulk's softening force-stretch law
// (eqs 23-25).
enum class ContactModel { Repulsive, LennardJones, InterfaceBonds };

// Points of different bodies repel with the short-range force of stiffness x the micromodulus
// once closer than d = min(distance x the finer spacing, initial_fraction x their distance at
// t = 0): LAMMPS's PERI package, d = min(0.9 |X_i - X_j|, 1.35 lattice constants) and 15 (Parks
// et al. 2008, after Silling's EMU manual). Model 2's bonds take d as their rest length.
struct Repulsion {
  double distance = 1.35;  // in spacings
  double initial_fraction = 0.9;
  double stiffness = 15.0;  // in micromoduli

  friend bool operator==(const Repulsion&, const Repulsion&) = default;
};

// Peridynamics' contact between bodies. (`contact.peridynamics` in a case file.)
struct PeridynamicsContact {
  ContactModel model = ContactModel::Repulsive;
  Repulsion repulsion;
  // Contact model 1 (PD paper eqs 15-22): phi = alpha [(r0/r)^m - 2 beta (r0/r)^n], cut off at
  // cutoff x r0. r0 is "a little larger than the node spacing" (the paper); ours is 1.1 of the
  // finer spacing of the pair of bodies. alpha, unset, follows from the bulk modulus (eq 22).
  double beta = 0.005;               // the paper's Fig 6(b)
  double r0 = 1.1;                   // in spacings
  double cutoff = 2.75;              // in r0 (the paper's R_c)
  std::optional<double> alpha;       // J
  double repulsion_exponent = 12.0;  // m
  double attraction_exponent = 6.0;  // n
  // Contact model 2 (PD paper eqs 23-25): the interface's fracture energy G_c, J/m^2, unset the
  // sum of the two materials' surface energies (the work of separating the metallic bond); the
  // critical stretch follows by eq 23, and the yield stretch s_y and softening m, unset, by the
  // fit of eq 24 to the bulk-fracture test (pd/laws/bulk_fracture.hpp).
  std::optional<double> fracture_energy;
  std::optional<double> yield_stretch;  // s_y
  std::optional<double> softening;      // m

  friend bool operator==(const PeridynamicsContact&, const PeridynamicsContact&) = default;
};

// Contact between bodies, each solver's under its own key (docs/input-reference.md, "contact");
// the keys before the split are moved to these when read (case/moved_keys.hpp).
struct Contact {
  MpmContact mpm;
  PeridynamicsContact peridynamics;

  friend bool operator==(const Contact&, const Contact&) = default;
};

enum class BondingModel { None, Strain, Energy };

// How eq 4.6 averages D_bond over a body's surface points at a node: divided by their count, as
// the thesis, or by the sum of their shape-function weights (docs/bonding.md).
enum class NodalAverage { Count, Weight };

// The direct bonding model (thesis Chapter 4). The thesis' code measured rates per microsecond;
// here they are per second (its Gdot_c = 2.271 J/m^2/us is 2.271e6 J/m^2/s). The energy model's
// defaults are the project's calibration for al-ptw on al-ptw with floor 0.1, r-z, 0.7/0.175 um
// (examples/calibration/al-energy.yaml; docs/validation/critical-velocity.md), not the
// thesis' G_c = 1503.74 J/m^2, Gdot_c = 2.271 J/m^2/us, which do not carry over to our floor.
// What happens to a bond under load (docs/bonding.md, "Debonding"): it holds for good (`none`,
// the thesis), or a bonded node carries at most a strength and lets go after a fracture energy,
// both in proportion to the bonded points' min(D_bond, 1) (`cohesive`: the extrinsic
// linear-softening law of Camacho and Ortiz 1996, mixed mode after Ortiz and Pandolfi 1999).
enum class DebondLaw { None, Cohesive };

struct Debond {
  // Off by default in impacts, on in every MPM pull-off (studies/pull_off.cpp): the shipped
  // calibration was fitted with bonds that hold for good (docs/bonding.md, "Debonding").
  DebondLaw law = DebondLaw::None;
  // The full bond's tensile strength, Pa; unset, the bonded points' own flow stress (the metal
  // next to a complete metallurgical bond).
  std::optional<double> strength;
  // The full bond's fracture energy, J/m^2; unset, Bonding::critical_energy (thesis §6.2: the
  // adhesion energy that formed the bond).
  std::optional<double> fracture_energy;
  double shear_ratio = 1.0;  // shear strength over tensile strength (Ortiz-Pandolfi's beta)

  friend bool operator==(const Debond&, const Debond&) = default;
};

struct Bonding {
  BondingModel model = BondingModel::None;
  double critical_strain = 1.4;            // eps_c, eq 4.4 (thesis §4.1.4's example)
  double critical_strain_rate = 8.5e8;     // 1/s (850 /us)
  double critical_energy = 416.59;         // G_c, J/m^2, eq 4.16b
  double critical_energy_rate = 9.502e11;  // Gdot_c, J/m^2/s (9.502e5 J/m^2/us)
  // eps_bond >= floor eps_c and G_bond >= floor G_c: the logarithm of eqs 4.4 and 4.16b
  // exceeds 1 at jetting rates and would make them negative (docs/bonding.md).
  double floor = 0.1;
  // A bond forms only once the impact that brought the pair together has penetrated this share
  // of the impacting body's size, and then wherever the pair touches (bodies/penetration.hpp,
  // docs/bonding.md "Activation"); 0: from the first contact where eq 4.7 says, the thesis'
  // model. Default: the project's calibration for al-ptw on al-ptw at D/40
  // (examples/calibration/al-activation.yaml, docs/validation/critical-velocity.md).
  double critical_penetration = 0.44248;
  NodalAverage nodal_average = NodalAverage::Weight;
  Debond debond;

  friend bool operator==(const Bonding&, const Bonding&) = default;
};

// The impact metrics (thesis §5.2.2) and the bonded verdict over the run's last window
// (metrics/verdict.hpp, docs/bonding.md).
struct ImpactMetrics {
  double rest_speed_limit = 60.0;        // m/s: v_rest averages points at or below this speed
  double bonded_separation_speed = 2.0;  // m/s: bonded needs the window's mean at most this
  double verdict_window = 20e-9;         // s: the verdict reads the run's last window
  int verdict_extensions = 2;            // windows a run is extended by while undecided, at most

  friend bool operator==(const ImpactMetrics&, const ImpactMetrics&) = default;
};

// How strongly a bond of the family counts in the shape tensor and the force state (PD paper
// eqs 5-7): omega = 1, or omega = delta / |xi|.
enum class Influence { Constant, InverseDistance };
// The stiffness of the zero-energy-mode control's increments: the material's elastic one in
// every direction, or, where the material flows, the tangent one along the flow direction
// (pd/control_along_flow.hpp).
enum class ControlStiffness { Elastic, Flow };

// The correspondence peridynamics solver (solver.method: peridynamics; docs/pd.md).
struct Peridynamics {
  double horizon_factor = 3.0;  // delta = horizon_factor x the body's spacing (PD paper: 3)
  Influence influence = Influence::Constant;
  // G_s of the zero-energy-mode control (Silling 2017): the penalty on the non-uniform part of a
  // bond's deformation, in units of the bond micromodulus 18 K / (pi delta^4).
  double stabilization = 0.1;
  ControlStiffness control_stiffness = ControlStiffness::Elastic;
  // Bodies whose stable step is shorter than the largest body's take several steps of their own
  // per step of it (pd/stepper.hpp, docs/pd.md "Subcycling"): bodies share no bonds, only contact.
  bool subcycling = false;

  friend bool operator==(const Peridynamics&, const Peridynamics&) = default;
};

// Planes of symmetry of the model, normal to x and to y: the bodies are cut there and the solver
// mirrors them (a quarter model of a normal impact: x = 0 and y = 0). Peridynamics; the MPM's
// symmetry planes are its fixed and roller grid faces.
struct Symmetry {
  std::optional<double> x;  // m
  std::optional<double> y;  // m

  friend bool operator==(const Symmetry&, const Symmetry&) = default;
};

// A rigid grip (the pull-off test, docs/pull-off.md): at t = 0 every point is set at rest, and
// the points of `body` in the last `fraction` of its extent along `side` (unset, zero: along
// `velocity`) are gripped: they move at `velocity` from then on, whatever the forces on them,
// reaching it smoothly over `ramp` ((1 - cos(pi t / ramp)) / 2), so that starting sends no
// stress wave.
struct Grip {
  std::string body;
  double fraction = 0.5;
  Vec3 velocity = Vec3::Zero();  // m/s
  Vec3 side = Vec3::Zero();      // a direction; zero: the velocity's
  double ramp = 0.0;             // s

  friend bool operator==(const Grip&, const Grip&) = default;
};

struct Probe {
  std::string name;
  Vec3 position = Vec3::Zero();
  std::vector<std::string> fields;  // pressure, sigma_xx..sigma_zz, velocity_x..z, ...

  friend bool operator==(const Probe&, const Probe&) = default;
};

struct Output {
  double history_interval = 0.0;   // s; 0 = every step
  double snapshot_interval = 0.0;  // s; 0 = first and last only
  std::vector<Probe> probes;
  // Checkpoints (run/checkpoints.hpp): every this much simulated time (0: none but the last)
  // and every this much wall-clock time, keeping the last checkpoint_keep of them.
  double checkpoint_interval = 0.0;         // s
  double checkpoint_wall_interval = 600.0;  // s
  int checkpoint_keep = 2;

  friend bool operator==(const Output&, const Output&) = default;
};

// Caps on a case's size, checked when the case is loaded, before anything is allocated: a case
// beyond them would exhaust the memory or run for ever (docs/reliability.md, "Input that cannot
// crash or stall"). An absent cap on points or grid nodes is computed from the memory available
// when the case is checked (case/size_limits.hpp).
struct Limits {
  std::optional<double> max_points;
  std::optional<double> max_grid_nodes;
  double max_steps = 1e8;

  friend bool operator==(const Limits&, const Limits&) = default;
};

struct Case {
  std::string name;
  std::string description;
  std::string source_file;  // path the case was read from
  // Where each key of the case was given: dotted key path (list items by name or index) ->
  // "FILE:LINE:COLUMN" or "--set KEY", for the errors that set-up finds after loading.
  std::map<std::string, std::string> key_locations;
  // Materials the bodies use, resolved (built-in, or user-defined with an optional base).
  std::map<std::string, materials::Material> materials;
  std::vector<Body> bodies;
  // Each solver's own section: both may be given, so that one case runs on either solver
  // (solver.method picks); the chosen solver's is required (the grid) or defaulted (peridynamics,
  // by load_case), the other is not used.
  std::optional<Grid> grid;
  Solver solver;
  std::optional<Peridynamics> peridynamics;
  std::optional<Symmetry> symmetry;
  std::optional<Grip> grip;
  Contact contact;
  Bonding bonding;
  ImpactMetrics metrics;
  Output output;
  Limits limits;
};

}  // namespace coldspray::case_file
