// Where the particles of `coldspray deposit` start (docs/deposit.md, "Placement"): their sizes
// drawn from a distribution, their speeds from a size law, their arrival times at random over a
// window and their centres at random over a patch of the substrate, without overlap; all from
// one seed, so the same file gives the same deposit.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace coldspray::studies {

// A particle size distribution. Samples lie within kSizeDeviations deviations of the centre
// (outside: drawn again), so that a normal distribution with centre > kSizeDeviations spread
// never gives a non-positive size, and the smallest particle, which sets how many points cross
// it, is known before drawing.
struct SizeDistribution {
  enum class Kind { Fixed, Normal, LogNormal };
  Kind kind = Kind::Fixed;
  double centre = 0.0;  // fixed: the size; normal: the mean; log-normal: the median, m
  double spread = 0.0;  // normal: standard deviation, m; log-normal: geometric standard deviation
                        // (> 1, dimensionless); fixed: unused

  double smallest() const;  // the smallest size it can draw, m
  double largest() const;   // the largest, m
};
inline constexpr double kSizeDeviations = 3.0;

struct DepositPlan {
  int count = 0;
  SizeDistribution diameter;
  // Impact speed against size, a power law v(d) = speed (d / speed_diameter)^speed_exponent, a
  // fit to the velocities a gun gives (measured or from a nozzle model); exponent 0: one speed.
  double speed = 0.0;           // m/s, at speed_diameter
  double speed_diameter = 0.0;  // m
  double speed_exponent = 0.0;
  std::array<double, 2> patch{};  // extent along x and y of the centres' patch, centred on 0, m
  double arrival_window = 0.0;    // s: arrival times are uniform over [0, window]
  double clearance = 0.0;         // the least gap between two particles' surfaces at t = 0, m
  std::uint64_t seed = 1;

  double speed_of(double diameter) const;  // the size law's speed, m/s
};

struct PlacedParticle {
  double diameter = 0.0;           // m
  double speed = 0.0;              // m/s, along -z
  double arrival = 0.0;            // s: when its bottom reaches z = 0, the substrate's top face
  std::array<double, 3> centre{};  // at t = 0, m
};

struct Placement {
  std::vector<PlacedParticle> particles;  // in arrival order
  // The particle (in the order drawn) that found no place without overlap in kPlacementTries
  // draws, the number placed before it; -1 when all were placed.
  int unplaced = -1;
};
inline constexpr int kPlacementTries = 1000;

// The diameters place_particles draws first, in the order drawn, m: what the deposit's size
// depends on, known before its particles are placed.
std::vector<double> draw_diameters(const DepositPlan& plan);

// Draws the sizes, then for each particle in turn an arrival time (the first's is 0: it touches
// the substrate at t = 0, as the thesis' first particle, §5.2.2; the others' uniform over the
// window) and a centre over the patch, both drawn again while the particle comes closer than the
// clearance to one placed before it, at most kPlacementTries times. Its bottom starts
// speed * arrival above z = 0, so that undisturbed it arrives at its time. The particles are then
// sorted by arrival. Interrupted (core/interrupt.hpp) at SIGINT or SIGTERM.
Placement place_particles(const DepositPlan& plan);

}  // namespace coldspray::studies
