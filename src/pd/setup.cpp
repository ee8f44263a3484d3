#include "pd/setup.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "bodies/grip.hpp"
#include "bodies/seed_bodies.hpp"
#include "case/located_error.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "pd/control_length.hpp"
#include "pd/deformation.hpp"
#include "pd/pair_forces.hpp"
#include "pd/symmetry.hpp"
#include "pd/tensor_field.hpp"

namespace coldspray::pd {

namespace {

// A shape tensor whose smallest eigenvalue is below this fraction of its largest belongs to a
// family that does not span three dimensions: F would not be defined (eq 5).
constexpr double kSingularShapeRatio = 1e-8;

// True if the symmetric matrix's smallest eigenvalue is below kSingularShapeRatio of its largest.
template <class Matrix>
bool singular(const Matrix& M) {
  const auto eigen = Eigen::SelfAdjointEigenSolver<Matrix>(M).eigenvalues();
  return !(eigen[0] > kSingularShapeRatio * eigen[eigen.size() - 1]);
}

// Eq 6 and the second-order fit's moment matrix (pd/quadratic_fit.hpp) at every point,
// inverted; throws InputError for a singular one.
void invert_moments(const case_file::Case& c, State& s) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const bodies::BodyRange& body = s.bodies[b];
    const BondWeights weights = bond_weights(s, b);
    for (std::size_t i = body.begin; i < body.end; ++i) {
      if (i % 4096 == 0) stop_set_up_if_interrupted("inverting the peridynamic shape tensors");
      const Eigen::Matrix3d K = shape_tensor(s.families, s.neighbours, weights, i);
      const MomentMatrix M = moment_matrix(s.families, s.neighbours, weights, i);
      if (singular(K) || singular(M))
        case_file::fail_at(
            c, fmt::format("bodies.{}.spacing", body.name),
            fmt::format("point {} of body '{}' has a family of {} neighbours that does not span "
                        "three dimensions (singular shape tensor, PD paper eq 6, or moment "
                        "matrix): give the body more points across its thinnest part or a larger "
                        "peridynamics.horizon_factor",
                        i - body.begin, body.name, s.family_size[i]));
      store_tensor(K.inverse(), s.shape_inverse, i);
      s.moment_inverse[i] = M.inverse();
      s.family_sums[i] = family_sums(s.families, s.neighbours, weights, i);
    }
  }
}

// The law between bodies a and b (pd/laws/registry.hpp): lengths from the finer spacing,
// constants from the softer material and the larger horizon, the same both ways.
ContactLaw contact_law(const case_file::Case& c, const State& s, std::size_t a, std::size_t b) {
  return make_contact_law({c, s.settings, s.bodies[a].material, s.bodies[b].material,
                           std::max(s.body_bonds[a].horizon, s.body_bonds[b].horizon),
                           std::min(s.bodies[a].material.elastic.bulk_modulus,
                                    s.bodies[b].material.elastic.bulk_modulus),
                           std::min(s.bodies[a].spacing, s.bodies[b].spacing)});
}

// Model 1 pushes apart with a force that grows as (r0/r)^(m+1): bodies must start no closer
// than its equilibrium distance (eq 17), or the first step would fling them apart.
void check_initial_gap(const case_file::Case& c, const State& s) {
  const Neighbours& N = s.neighbours;
  for (std::size_t i = 0; i < N.real; ++i)
    for (std::size_t k = s.contact.begin[i]; k < s.contact.begin[i + 1]; ++k) {
      const std::size_t j = s.contact.other[k];
      const auto* law = std::get_if<LennardJones>(&contact_law_between(s, i, j));
      if (law == nullptr) continue;
      const double r = (N.position[i] - N.position[j]).head<3>().norm();
      // Closer than both r_e and the cut-off: pushed apart at t = 0.
      const double r_e = equilibrium_distance(law->potential);
      if (r < r_e && r < law->reach)
        case_file::fail_at(
            c, "contact.peridynamics.model",
            fmt::format("bodies '{}' and '{}' start {:.4g} um apart (points {} and {}), closer "
                        "than the Lennard-Jones equilibrium distance r0 (2 n beta / m)^(-1/(m-n)) "
                        "= {:.4g} um (PD paper eq 17): place them at least that far apart "
                        "(`coldspray impact --contact lennard-jones` does)",
                        s.bodies[N.body[i]].name, s.bodies[N.body[j]].name, r * 1e6, i, j,
                        r_e * 1e6));
    }
}

// The bodies seeded, cut at the model's symmetry planes and laid out as the state's points.
std::vector<bodies::SeededBody> seed_points(const case_file::Case& c, State& s) {
  std::vector<bodies::SeededBody> seeded = bodies::seed_bodies(c);
  if (c.symmetry) {
    s.symmetry_plane = {c.symmetry->x, c.symmetry->y};
    std::vector<bodies::CutPlane> planes;
    for (int axis = 0; axis < 2; ++axis)
      if (s.symmetry_plane[axis]) planes.push_back({axis, *s.symmetry_plane[axis], true});
    bodies::cut_at_planes(c, planes, "its symmetry planes", seeded);
  }
  bodies::lay_out_bodies(c, seeded, s);
  return seeded;
}

// The neighbour search's reference positions, the force arrays and each body's signal speed.
void init_point_arrays(State& s) {
  const std::size_t n = s.points.size();
  Neighbours& N = s.neighbours;
  N.real = n;
  N.volume = s.points.volume0;
  N.body = s.points.body;
  N.reference.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    N.reference[i] = {s.points.position[0][i], s.points.position[1][i], s.points.position[2][i],
                      0.0};
  for (int d = 0; d < 3; ++d) {
    s.acceleration[d].assign(n, 0.0);
    s.control_force[d].assign(n, 0.0);
    s.contact_force[d].assign(n, 0.0);
    s.external_force[d].assign(n, 0.0);
    s.contact_kick[d].assign(n, 0.0);
  }
  s.advancing.assign(s.bodies.size(), 1);
  s.fast_bodies.assign(s.bodies.size(), 0);
  s.body_signal_speed.assign(s.bodies.size(), 0.0);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (std::size_t i = s.bodies[b].begin; i < s.bodies[b].end; ++i) {
      const double speed = std::sqrt(s.points.velocity[0][i] * s.points.velocity[0][i] +
                                     s.points.velocity[1][i] * s.points.velocity[1][i] +
                                     s.points.velocity[2][i] * s.points.velocity[2][i]);
      s.body_signal_speed[b] = std::max(s.body_signal_speed[b], s.points.sound_speed[i] + speed);
    }
}

// Each body's bond constants: horizon delta, the micromodulus 18 K / (pi delta^4) and the
// control's G_s over the control length; returns the horizons.
std::vector<double> init_bond_constants(State& s) {
  std::vector<double> horizons;
  s.min_spacing = s.bodies.front().spacing;
  for (const bodies::BodyRange& body : s.bodies) {
    const double delta = s.settings.horizon_factor * body.spacing;
    const double K = body.material.elastic.bulk_modulus;
    const double micromodulus = 18.0 * K / (std::numbers::pi * std::pow(delta, 4));
    const double l = control_length(s.settings.influence, delta, body.spacing);
    s.body_bonds.push_back({delta, micromodulus, s.settings.stabilization * micromodulus / l});
    horizons.push_back(delta);
    s.min_spacing = std::min(s.min_spacing, body.spacing);
  }
  return horizons;
}

// The per-point and per-neighbour arrays of the correspondence step, sized to the families.
void init_family_arrays(const case_file::Case& c, State& s) {
  const std::size_t n = s.points.size();
  const Neighbours& N = s.neighbours;
  s.family_size.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    s.family_size[i] = static_cast<std::uint32_t>(s.families.begin[i + 1] - s.families.begin[i]);

  s.shape_inverse.assign(n, Eigen::Matrix3d::Zero());
  s.moment_inverse.assign(n, MomentMatrix::Zero());
  s.family_sums.assign(n, FamilySums{});
  s.deformation_gradient.assign(n, Eigen::Matrix3d::Identity());
  s.compressed_stretch.assign(n, 1.0);
  s.piola_over_shape.assign(N.size(), PaddedTensor::Zero());
  s.velocity_fit.assign(N.size(), QuadraticMap::Zero());
  s.flow_direction.assign(N.size(), PaddedTensor::Zero());
  s.flow_softening.assign(N.size(), 0.0);
  invert_moments(c, s);
  s.pairs = pair_schedule(s.families, n);
  s.pair_bonds.assign(n, Eigen::Vector4d::Zero());
  s.pair_control.assign(n, Eigen::Vector4d::Zero());
  if (s.settings.control_stiffness == case_file::ControlStiffness::Flow) {
    s.control_displacement.assign(s.pairs.pair_index[n], Eigen::Vector3d::Zero());
    s.slip_fit.assign(N.size(), QuadraticMap::Zero());
    s.slipped.assign(N.size(), 0);
  }
}

// Which axes of each point are held: fixed faces in all three, roller faces normal to the face.
void hold_faces(const case_file::Case& c, const std::vector<bodies::SeededBody>& seeded, State& s) {
  s.held.assign(s.points.size(), 0);
  bodies::prepare_grip(s, c.grip);
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const std::uint8_t fixed = bodies::faces_bits(c.bodies[b].fixed);
    for (const case_file::BodyFace face : c.bodies[b].roller) {
      const std::uint8_t bits = bodies::faces_bits({face});
      const std::uint8_t axes = face == case_file::BodyFace::Side ? 0b011 : 0b100;
      for (std::size_t i = 0; i < seeded[b].points.outside.size(); ++i)
        if (seeded[b].points.outside[i] & bits) s.held[s.bodies[b].begin + i] |= axes;
    }
    for (std::size_t i = 0; i < seeded[b].points.outside.size(); ++i)
      if (seeded[b].points.outside[i] & fixed) s.held[s.bodies[b].begin + i] = 0b111;
  }
}

// The contact law of every pair of bodies and the contact list built to the largest reach.
void set_up_contact(const case_file::Case& c, State& s) {
  const Neighbours& N = s.neighbours;
  const std::size_t m = s.bodies.size();
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < m; ++b) s.contact_law.push_back(contact_law(c, s, a, b));
  s.contact.skin = 0.5 * s.min_spacing;
  // Model 2's bonds keep their largest stretch beside the list (pd/laws/interface_bonds.hpp).
  s.contact.remembers_stretch = std::any_of(
      s.contact_law.begin(), s.contact_law.end(),
      [](const ContactLaw& law) { return std::holds_alternative<InterfaceBonds>(law); });
  // An adhesive contact can hold a body: the verdict then reads the area it holds.
  s.bonding = any_adhesive(s.contact_law);
  s.contact.build(N, largest_reach(s.contact_law) + s.contact.skin);
}

}  // namespace

State build_state(const case_file::Case& c) {
  State s;
  s.settings = *c.peridynamics;
  s.viscosity = c.solver.artificial_viscosity;
  s.cfl = c.solver.cfl;
  const std::vector<bodies::SeededBody> seeded = seed_points(c, s);
  init_point_arrays(s);
  const std::vector<double> horizons = init_bond_constants(s);
  add_ghosts(s);
  refresh_neighbours(s);
  s.families = build_families(s.neighbours, s.bodies, horizons);
  s.discretisation = {"peridynamics", "horizon",
                      *std::min_element(horizons.begin(), horizons.end()), s.families.bonds()};
  init_family_arrays(c, s);
  hold_faces(c, seeded, s);
  set_up_contact(c, s);
  check_initial_gap(c, s);
  return s;
}

}  // namespace coldspray::pd
