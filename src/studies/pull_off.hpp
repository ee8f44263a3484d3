// The numerical pull-off test (PD paper Fig 11; docs/pull-off.md): an impacted splat, from its
// run's last checkpoint at rest, pulled from the substrate by a rigid grip on its upper part
// while the substrate's bottom stays held; the force across the interface against the grip's
// displacement, its peak, the work of separation and the adhesion strength.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace coldspray::studies {

struct PullOffOptions {
  std::filesystem::path impact;  // the impact's run folder
  std::filesystem::path out;     // the pull-off's folder (its run in out / "run")
  double speed = 10.0;           // m/s, the grip's once its ramp is over
  bool shear = false;            // tangential (x) instead of normal to the substrate
  double distance = 0.0;         // m the grip travels; 0: three spacings of the gripped body
  std::string body;              // the gripped body; empty: the one that moved at t = 0
  double fraction = 0.5;         // of the body's extent along the pull that the grip holds
  bool progress = true;
};

struct PullOffResult {
  std::vector<double> displacement;  // of the grip, m
  std::vector<double> force;         // across the interface along the pull, whole body, N
  double peak_force = 0.0;           // N
  double peak_displacement = 0.0;    // m
  double work = 0.0;                 // of separation: the integral of the force where > 0, J
  double final_force = 0.0;          // N, at the end
  double bonded_area = 0.0;          // m^2, the body's points the substrate acted on at the start
  double projected_area = 0.0;       // m^2, its footprint
  bool separated = false;            // the force had fallen to 1 % of its peak by the end
};

// Runs the test into options.out and returns what it measured; also writes out / pull_off.csv
// and out / summary.json. InputError if the impact folder holds no checkpoint, is an MPM result,
// or the options do not fit it.
PullOffResult pull_off(const PullOffOptions& options);

}  // namespace coldspray::studies
