// The material points of all bodies, whichever solver moves them, as structure of arrays (one
// array per quantity), so the step's loops stream through memory. Points are stored body after
// body: each body's points are one contiguous range, which lets the stress update dispatch on the
// material once per body.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace coldspray::bodies {

// Components of a symmetric tensor in the order xx, yy, zz, xy, yz, xz. In axisymmetric runs
// x is r, y is the hoop direction theta and z the axis.
enum SymmetricComponent { kXX = 0, kYY, kZZ, kXY, kYZ, kXZ };

struct Points {
  // Kinematics.
  std::array<std::vector<double>, 3> position;  // m
  std::array<std::vector<double>, 3> velocity;  // m/s
  std::vector<double> mass;                     // kg, constant
  std::vector<double> volume0;                  // m^3, reference volume (ring volume in r-z)
  // Half-widths along x, y, z, m: half the spacing at t = 0, then stretched with the material
  // along each axis (MPM: the axis-aligned form of convected-domain GIMP's particle domain).
  std::array<std::vector<double>, 3> half_width;

  // Material state: what materials::PointState carries from step to step, spread over arrays.
  // (Its diagnostics melt_temperature and pressure are not kept: the pressure is the stress's
  // mean, materials::mean_pressure, and nothing reads the melt temperature.)
  std::array<std::vector<double>, 6> stress;  // Cauchy, Pa, tension positive
  std::vector<double> eqps;
  std::vector<double> eqps_rate;      // 1/s
  std::vector<double> return_slope;   // Pa
  std::vector<double> temperature;    // K
  std::vector<double> energy;         // internal energy per reference volume, J/m^3
  std::vector<double> J;              // V/V0
  std::vector<double> flow_stress;    // Pa
  std::vector<double> shear_modulus;  // Pa

  // Bookkeeping.
  std::vector<double> sound_speed;     // longitudinal wave speed after the last update, m/s
  std::vector<double> bulk_viscosity;  // artificial viscous pressure q of the last step, Pa
  std::vector<double> plastic_work;    // accumulated plastic work, J
  std::vector<double> viscous_work;    // accumulated work of the bulk viscosity, J
  std::vector<double> contact_work;    // accumulated work of the contact corrections, J
  std::vector<std::uint16_t> body;     // index into the run's body list
  std::vector<std::uint8_t> surface;   // 1 on the body's initial surface (bonding set S)
  std::vector<double> initial_z;       // z at t = 0, m (crater depth)
  // The point's index among its body's points at t = 0, which it keeps when points before it
  // leave the grid (mpm/departures.hpp): ascending within each body.
  std::vector<std::uint32_t> id;

  // Bonding (thesis Chapter 4): D_bond, and whether the surface point has touched another
  // body (ever, and in this step, with its body's outward contact normal). `bonded_to` keeps the
  // bond: 1 + the body the point bonded to at a node where a bond formed (eq 4.7), 0 while it
  // has not; the bond force acts wherever bonded points of both bodies meet (mpm/contact.hpp).
  std::vector<double> bond;
  std::vector<std::uint16_t> bonded_to;
  // The bond's damage under the debonding law (bonding/cohesive_law.hpp), 0 intact: at 1 the
  // point lets go of its bond for good and no longer counts towards a new one.
  std::vector<double> bond_damage;
  std::vector<std::uint8_t> touched;
  std::vector<std::uint8_t> touching;
  std::array<std::vector<double>, 3> contact_normal;

  // Per-step scratch, kept here so the step loop allocates nothing.
  std::array<std::vector<double>, 3> displacement;  // x^{k+1} - x^k from the grid velocities

  std::size_t size() const { return mass.size(); }
  void resize(std::size_t n);

  // Calls f(name, v) for every per-point array v (a std::vector of doubles or of integers), with
  // its name in the checkpoints (checkpoint/fields.hpp): the one list of what a point carries.
  template <class F>
  void for_each_named_array(F&& f) {
    static constexpr const char* kAxes[] = {"_x", "_y", "_z"};
    static constexpr const char* kComponents[] = {"_xx", "_yy", "_zz", "_xy", "_yz", "_xz"};
    auto axes = [&](const char* name, std::array<std::vector<double>, 3>& a) {
      for (int d = 0; d < 3; ++d) f(std::string(name) + kAxes[d], a[d]);
    };
    axes("position", position);
    axes("velocity", velocity);
    axes("half_width", half_width);
    axes("contact_normal", contact_normal);
    axes("displacement", displacement);
    for (int c = 0; c < 6; ++c) f(std::string("stress") + kComponents[c], stress[c]);
    f("mass", mass), f("volume0", volume0), f("eqps", eqps), f("eqps_rate", eqps_rate);
    f("return_slope", return_slope), f("temperature", temperature), f("energy", energy);
    f("J", J), f("flow_stress", flow_stress), f("shear_modulus", shear_modulus);
    f("sound_speed", sound_speed), f("bulk_viscosity", bulk_viscosity);
    f("plastic_work", plastic_work), f("viscous_work", viscous_work);
    f("contact_work", contact_work), f("initial_z", initial_z), f("bond", bond);
    f("surface", surface), f("touched", touched), f("touching", touching), f("body", body);
    f("bonded_to", bonded_to), f("id", id), f("bond_damage", bond_damage);
  }
  // Calls f(v) for every per-point array v.
  template <class F>
  void for_each_array(F&& f) {
    for_each_named_array([&](const std::string&, auto& v) { f(v); });
  }
};

// The speed |v| of point p, m/s.
inline double speed(const Points& P, std::size_t p) {
  const double v[3] = {P.velocity[0][p], P.velocity[1][p], P.velocity[2][p]};
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace coldspray::bodies
