// `coldspray material-test`: one material point driven along a homogeneous loading path through
// the same stress update the solvers use (materials/stress_update.hpp).
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

#include "materials/material.hpp"

namespace coldspray::material_test {

enum class Mode {
  UniaxialStrain,  // L = diag(r, 0, 0)
  UniaxialStress,  // L = diag(r, a, a), a solved each step so that sigma_yy = sigma_zz = 0
  SimpleShear,     // L_xy = r: strain is the engineering shear gamma
};

// Throws InputError (where = "--mode") for an unknown name.
Mode parse_mode(std::string_view name);

// The most steps a loading takes. Every sample is kept (88 bytes) and written as a CSV row (about
// 200 bytes); without a bound `--steps 2147483647` reserved 190 GB up front (std::bad_alloc,
// exit 1), and 10^8 steps ran for minutes. A curve needs thousands (the default is 2000).
inline constexpr int kMaxSteps = 1'000'000;

struct Loading {
  Mode mode = Mode::UniaxialStrain;
  double strain_rate = 1.0;    // magnitude r of the driving rate, 1/s, > 0
  double final_strain = -0.1;  // signed: negative is compression (log strain, or gamma in shear)
  double temperature = 298.0;  // initial, K
  bool isothermal = false;
  int steps = 2000;  // 1 to kMaxSteps
};

// One row of the output; SI.
struct Sample {
  double time = 0.0;
  double strain = 0.0;
  double eqps = 0.0;
  double eqps_rate = 0.0;
  double temperature = 0.0;
  double melt_temperature = 0.0;
  double shear_modulus = 0.0;
  double flow_stress = 0.0;
  double von_mises = 0.0;
  double pressure = 0.0;
  double density = 0.0;
};

// Checks the loading (InputError naming the option on a bad value), then drives the point,
// calling `record` with the initial state and after every step. Throws RunFault if the state
// becomes non-finite or the uniaxial-stress lateral iteration fails.
void drive(const materials::Material& material, const Loading& loading,
           const std::function<void(const Sample&)>& record);

// CSV with the header time,strain,eqps,eqps_rate,temperature,melt_temperature,shear_modulus,
// flow_stress,von_mises,pressure,density.
void write_csv_header(std::ostream& out);
void write_csv_row(std::ostream& out, const Sample& s);

}  // namespace coldspray::material_test
