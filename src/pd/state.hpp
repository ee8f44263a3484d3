// Everything a peridynamics run carries from step to step: the bodies (bodies/bodies.hpp) and
// what correspondence PD adds to them. Built once by pd/setup.hpp; the step (pd/stepper.hpp)
// only reads and writes it, allocating nothing (but the contact list, which grows when more
// pairs come close than ever before).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "pd/contact.hpp"
#include "pd/deformation.hpp"
#include "pd/families.hpp"
#include "pd/laws/registry.hpp"
#include "pd/neighbours.hpp"
#include "pd/quadratic_fit.hpp"

namespace coldspray::pd {

// A 3x3 tensor per point, each point's nine components together: the bond loops read a
// neighbour's whole tensor at once (nine separate arrays cost nine cache lines per neighbour).
using TensorField = std::vector<Eigen::Matrix3d>;
// The same with a fourth, zero row, so that each column is one four-double (AVX) register, for
// the tensor the force loop reads at every neighbour (pd/forces.cpp).
using PaddedTensor = Eigen::Matrix<double, 4, 3>;
using PaddedTensorField = std::vector<PaddedTensor>;

// What a body's bonds need: its horizon delta, the bond micromodulus 18 K / (pi delta^4) of
// its material (Silling and Askari, Comput. Struct. 83 (2005), eq 23 of the PD paper's ref 49),
// the unit of the stabilisation and of the contact force, and the zero-energy-mode control's
// constant G_s c / l (pd/control_length.hpp).
struct BodyBonds {
  double horizon = 0.0;       // m
  double micromodulus = 0.0;  // N/m^6
  double control = 0.0;       // G_s c / l, N/m^7
};

// A ghost: the image of real point `source` mirrored across the x plane (flips bit 0), the y
// plane (bit 1) or both.
struct Ghost {
  std::uint32_t source = 0;
  std::uint8_t flips = 0;
};

// The order in which pd/pair_forces.hpp visits each pair of neighbours once: per real point the
// first bond whose neighbour index exceeds its own, and the point blocks [block[k],
// block[k + 1]) that run in parallel two colours at a time.
// pair_index[i] numbers i's first pair; its pairs follow in family order (real points only).
struct PairSchedule {
  std::vector<std::size_t> first_pair;
  std::vector<std::size_t> pair_index;
  std::vector<std::size_t> block;
  // The number of the pair (i, j > i) whose j is at `bond` in i's family.
  std::size_t pair(std::size_t i, std::size_t bond) const {
    return pair_index[i] + bond - first_pair[i];
  }
};

struct State : bodies::Bodies {
  case_file::Peridynamics settings;
  case_file::ArtificialViscosity viscosity;
  std::vector<BodyBonds> body_bonds;

  // The symmetry planes' positions along x and y, if any, and the ghost points they mirror.
  std::array<std::optional<double>, 2> symmetry_plane;
  std::vector<Ghost> ghosts;
  Neighbours neighbours;  // the real points, then the ghosts (their X, y, v, V0, body)

  Families families;  // of the real points, into `neighbours`
  PairSchedule pairs;
  TensorField shape_inverse;  // K^-1 (eq 6) of the real points, 1/m^5
  // M^-1 of the second-order fit (pd/quadratic_fit.hpp) of the real points, 1/m^3.
  std::vector<MomentMatrix> moment_inverse;
  std::vector<FamilySums> family_sums;  // of the real points
  TensorField deformation_gradient;     // F (eq 5) of the last force evaluation, real points
  // min(1, the smallest principal stretch of F) of the real points (pd/time_step.hpp).
  std::vector<double> compressed_stretch;
  // Of the last force evaluation, of the real points and then the ghosts: A = P K^-1
  // (P = J (sigma - q I) F^-T, eq 7's P, Pa/m^5), the second-order fit Cdot of the velocities
  // (1/s), and what the control's stiffness along the flow needs (pd/control_scale.hpp): the
  // unit flow direction N = s / |s| (padded) and the softening 1 - H / (3G + H), 0 where the
  // point did not flow in the step or the control is elastic.
  PaddedTensorField piola_over_shape;
  std::vector<QuadraticMap> velocity_fit;
  PaddedTensorField flow_direction;
  std::vector<double> flow_softening;
  // The bond and control force densities of the real points (pd/pair_forces.hpp): N/m^3 for the
  // bonds, N/m^3/s for the control's rate.
  std::vector<Eigen::Vector4d> pair_bonds, pair_control;
  // With the control along the flow (pd/control_along_flow.hpp), each pair's penalty
  // displacement e, m, seen from its lower index (PairSchedule::pair_index), and per point (real,
  // then ghosts) the second-order fit of half the pairs' slip rates, 1/s; empty otherwise.
  std::vector<Eigen::Vector3d> control_displacement;
  std::vector<QuadraticMap> slip_fit;
  std::vector<std::uint8_t> slipped;                // whether a point's slip fit is not zero
  std::array<std::vector<double>, 3> acceleration;  // m/s^2
  // The zero-energy-mode control's force density, accumulated step by step from its rate
  // (pd/forces.hpp), and the last contact force density, N/m^3, whose works the step books once
  // the velocities are those of the step's end.
  std::array<std::vector<double>, 3> control_force, contact_force;
  std::array<std::vector<double>, 3> external_force;  // the dashpots' and the grip's forces, N
  // Per point, the velocity components held at zero: bit d for axis d (fixed and roller faces).
  std::vector<std::uint8_t> held;

  ContactList contact;
  std::vector<ContactLaw> contact_law;  // per ordered body pair [a * bodies + b]
  double min_spacing = 0.0;             // the smallest body spacing, m (the time step's length)

  // Per body, max over its points of (c + |v|) / min(1, lambda / 0.7) after its last stress
  // update (pd/time_step.hpp), m/s: with its spacing, its own stable step.
  std::vector<double> body_signal_speed;
  // Subcycling (settings.subcycling, pd/stepper.hpp): solver.cfl, which sets each body's stable
  // step; per body, whether the phase of the step under way advances it and whether it takes
  // substeps; the contact impulse density a slow body's point takes in a kick, N s/m^3; and the
  // substeps of the last step.
  double cfl = 0.0;
  std::vector<std::uint8_t> advancing, fast_bodies;
  std::array<std::vector<double>, 3> contact_kick;
  int substeps = 1;
};

// The contact law between points i and j (real or ghost) of different bodies.
inline const ContactLaw& contact_law_between(const State& s, std::size_t i, std::size_t j) {
  return s.contact_law[s.neighbours.body[i] * s.bodies.size() + s.neighbours.body[j]];
}

// The bond weights of body b's families (pd/deformation.hpp).
inline BondWeights bond_weights(const State& s, std::size_t b) {
  return {s.settings.influence, s.body_bonds[b].horizon};
}

// Models of fewer points step on one thread whatever --threads says: the `if` of every parallel
// loop of the step (docs/reliability.md, "Threads on a loaded machine"). A step forks 17 teams;
// a 252-point model holds ~25 us of work per loop, and while the other core is busy each fork
// and join waits for a descheduled thread, up to libgomp's spin (300 000 pauses, 3-7 ms here):
// its pull-off took 0.13 s on 2 threads idle, 0.15 s on 1, and 17-34 s on 2 threads beside two
// busy loops (0.3-0.4 s on 1). Either way the loops run the same iterations in the same order.
// The bound is low: idle, the 560-point spheres still step 1.6 times faster on 2 threads, the
// 240-point ones 1.26 times on steps of 0.2 ms; below it a thread saves at most that fraction
// of a millisecond a step.
constexpr std::size_t kMinThreadedPoints = 500;

inline bool threaded(const State& s) { return s.points.size() >= kMinThreadedPoints; }

}  // namespace coldspray::pd
