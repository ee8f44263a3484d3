// What every solver's state is: the bodies' points and ranges, the boundary points, the energy
// ledger of points that left, the contact impulses between bodies, and the clock. The recorder,
// the metrics and the studies read only this (docs/architecture.md, "Two solvers, one seam"); a
// solver's own state (mpm::State) extends it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bodies/penetration.hpp"
#include "bodies/points.hpp"
#include "case/case.hpp"
#include "materials/material.hpp"

namespace coldspray::bodies {

// What a body's points carried off when they left the computation (mpm/departures.hpp), summed
// over them in index order at the end of the step in which each left.
struct Departed {
  std::size_t points = 0;
  double mass = 0.0;                 // kg
  std::array<double, 3> momentum{};  // kg m/s
  double kinetic = 0.0;              // 1/2 m v^2, J
  double internal = 0.0;             // E V0, J
  double plastic_work = 0.0;         // J, part of internal
  double viscous_work = 0.0;         // J
  double contact_work = 0.0;         // J
  double absorbed = 0.0;             // work done on their dashpots, J (absorbing-face points)
};

struct BodyRange {
  std::string name;
  std::size_t begin = 0;  // the body's points are [begin, end)
  std::size_t end = 0;
  materials::Material material;
  double spacing = 0.0;
  std::array<double, 3> initial_velocity{};  // m/s
  double initial_diameter = 0.0;             // lateral extent at t = 0, m
  // Where the body was cut by a symmetry plane normal to x or y (in r-z, x = r is cut at the
  // axis r = 0): the whole body is the modelled part and its mirror image, so its centre lies on
  // the plane and its areas are twice the modelled part's.
  std::array<std::optional<double>, 2> mirror_plane{};
  Departed departed{};        // the body's points that have left the computation
  Penetration penetration{};  // its push into what it hit, bonding's activation (penetration.hpp)
};

// A point on an absorbing face: Lysmer-Kuhlemeyer dashpots (thesis §3.5.5, eqs 3.45-3.46) give
// it the force -damping[a] * v_a along each axis a.
struct AbsorbingPoint {
  std::size_t point = 0;
  std::array<double, 3> damping{};  // N s/m
  double absorbed = 0.0;            // work done on the dashpots so far, J
};

// A fault found during a step: the lowest point index at fault, so the report is the same
// whatever the threads.
struct Fault {
  std::size_t point = std::numeric_limits<std::size_t>::max();
  // A string literal: faults are recorded inside parallel regions, where an allocation's
  // exception could not leave the region and would abort the program.
  const char* cause = "";
};

// Records a fault at point p unless one at a lower index is recorded (safe to call from
// threads), so the report is the same whatever the threads.
void record_fault(Fault& fault, std::size_t p, const char* cause) noexcept;

struct Bodies;
// Throws RunFault naming the body, point (its index at t = 0), position, time and cause of the
// recorded fault, if there is one.
void raise_recorded_fault(const Bodies& s);

// Which solver moves the bodies, and its discretisation, for the summary.
struct Discretisation {
  std::string method;       // "mpm" or "peridynamics"
  std::string length_name;  // the length's name in summary.json: "cell_size" or "horizon"
  double length = 0.0;      // the MPM's cell size, or the smallest PD horizon, m
  // PD only: neighbour pairs in the families (each counted from both ends).
  std::optional<std::size_t> bonds;
};

struct Bodies {
  Discretisation discretisation;
  case_file::Geometry geometry = case_file::Geometry::ThreeD;
  Points points;
  std::vector<BodyRange> bodies;
  std::vector<AbsorbingPoint> absorbing;
  // Impulse received by body a from body b in the last step, flattened [a * bodies + b], N s.
  std::vector<std::array<double, 3>> contact_impulse;
  // The bonding model is on: bonds can form and hold a particle (the verdict, metrics/verdict.hpp).
  bool bonding = false;
  case_file::ImpactMetrics impact_metrics;
  // Peridynamics: the neighbours in each point's family (the snapshots' `neighbours`); empty for
  // the MPM.
  std::vector<std::uint32_t> family_size;
  // Per point, 1 if the pull-off test's grip moves it (bodies/grip.hpp), at grip_velocity after
  // its ramp.
  std::vector<std::uint8_t> gripped;
  Eigen::Vector3d grip_velocity = Eigen::Vector3d::Zero();  // m/s
  double grip_ramp = 0.0;                                   // s

  double time = 0.0;
  double dt = 0.0;
  long step = 0;
  double max_signal_speed = 0.0;  // max over points of c + |v| after the last stress update
  Fault fault;
};

}  // namespace coldspray::bodies
