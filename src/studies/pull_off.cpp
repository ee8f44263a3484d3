#include "studies/pull_off.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_columns.hpp"
#include "run/checkpoints.hpp"
#include "run/interface_areas.hpp"
#include "run/run.hpp"
#include "run/solver.hpp"
#include "studies/pull_off_fields.hpp"

namespace coldspray::studies {
namespace {

// The grip reaches its speed over this share of the run (pd/grip.hpp's ramp): long against the
// time a wave takes to cross a splat, so that the start sends none through it.
constexpr double kRampShare = 0.2;

// The force has fallen back to this share of its peak: the splat has let go.
constexpr double kSeparatedShare = 0.01;

std::size_t gripped_body(const case_file::Case& c, const PullOffOptions& o) {
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (!o.body.empty() ? c.bodies[b].name == o.body : c.bodies[b].velocity.norm() > 0.0) return b;
  }
  if (!o.body.empty())
    throw InputError("--body", "", fmt::format("no body '{}' in {}", o.body, o.impact.string()));
  throw InputError(o.impact.string(), "",
                   "has no body that moved at t = 0 to pull off: name it with --body");
}

// Away from the substrate: against the body's impact velocity (+z if it had none).
Eigen::Vector3d away_from_substrate(const case_file::Case& c, std::size_t body) {
  const Eigen::Vector3d v0 = c.bodies[body].velocity;
  // (0 - v: no negative zeros in summary.json.)
  return v0.norm() > 0.0 ? Eigen::Vector3d(Eigen::Vector3d::Zero() - v0.normalized())
                         : Eigen::Vector3d::UnitZ();
}

// The pull's direction: away from the substrate, or, in shear, along x, which needs a model
// that is neither r-z nor cut at x = const.
Eigen::Vector3d pull_direction(const case_file::Case& c, std::size_t body,
                               const metrics::InterfaceAreas& areas, const PullOffOptions& o) {
  if (!o.shear) return away_from_substrate(c, body);
  if (areas.axisymmetric)
    throw InputError("--direction", "",
                     "shear pushes along x, which an axisymmetric (r-z) model cannot: pull off a "
                     "3D model");
  if (areas.mirror_plane[0])
    throw InputError("--direction", "",
                     "shear pulls along x, across the impact's symmetry plane x = " +
                         fmt::format("{:g}", *areas.mirror_plane[0] * 1e6) +
                         " um: pull off a whole model (impact --symmetry none)");
  return Eigen::Vector3d::UnitX();
}

// From the modelled part to the whole: 2 per symmetry plane the pull lies in (the force across
// the interface is the same on both sides of it); an r-z model's forces are its rings'.
double whole_factor(const metrics::InterfaceAreas& areas, const Eigen::Vector3d& direction) {
  if (areas.axisymmetric) return 1.0;
  double factor = 1.0;
  for (int d = 0; d < 2; ++d)
    if (areas.mirror_plane[d] && direction[d] == 0.0) factor *= 2.0;
  return factor;
}

// Each bonded point's strength at the start of the pull, for the radial profile.
void write_interface(const std::filesystem::path& file, const metrics::InterfaceAreas& areas) {
  io::write_atomically(file, [&](std::ostream& out) {
    out << "x,y,z,radius,area,bond,damage,strength,critical_opening\n";
    for (const metrics::InterfacePoint& q : areas.points)
      out << fmt::format(
          "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n",
          q.position[0], q.position[1], q.position[2], q.radius, q.area, q.bond, q.damage,
          q.strength, q.critical_opening);
  });
}

// The grip's travel at time t: the integral of its ramped speed (pd/grip.hpp).
double grip_travel(double speed, double ramp, double t) {
  if (t >= ramp) return speed * (t - 0.5 * ramp);
  return speed *
         (0.5 * t - ramp / (2.0 * std::numbers::pi) * std::sin(std::numbers::pi * t / ramp));
}

void write_results(const PullOffOptions& o, const PullOffResult& r, const std::string& body,
                   const Eigen::Vector3d& direction) {
  io::write_atomically(o.out / "pull_off.csv", [&](std::ostream& out) {
    out << "displacement,force\n";
    for (std::size_t k = 0; k < r.force.size(); ++k)
      out << fmt::format("{:.10g},{:.10g}\n", r.displacement[k], r.force[k]);
  });
  write_pull_off_summary(o.out / "summary.json", PullOffSummary{o, r, body, direction});
}

}  // namespace

PullOffResult pull_off(const PullOffOptions& o) {
  const std::filesystem::path checkpoint = run::find_checkpoint(o.impact);
  const case_file::Case impact = run::checkpoint_case(checkpoint);
  case_file::Case c = impact;
  // What differs by solver: what holds a bond, its default travel, what is held (mpm/answers.hpp,
  // pd/answers.hpp).
  run::with_solver(c.solver.method, [&](auto solver) { debond_during_pull(solver, c); });
  if (!(o.speed > 0.0)) throw InputError("--speed", "", "must be positive");
  if (!(o.fraction > 0.0 && o.fraction <= 1.0)) throw InputError("--grip", "", "must be in (0, 1]");
  const std::size_t body = gripped_body(c, o);
  PullOffResult r;
  const metrics::InterfaceAreas areas = run::interface_areas(c, checkpoint, body);
  r.bonded_area = areas.bonded;
  r.projected_area = areas.projected;
  const Eigen::Vector3d direction = pull_direction(c, body, areas, o);
  run::with_solver(c.solver.method, [&](auto solver) {
    if (!holds_bonds(solver, c))
      throw InputError(o.impact.string(), "", std::string(unbonded_reason(solver)));
  });
  const double distance =
      o.distance > 0.0 ? o.distance : run::with_solver(c.solver.method, [&](auto solver) {
        return default_pull_distance(solver, c, body, areas);
      });
  const double duration = distance / o.speed;

  // The pull: the impact's case from its checkpoint's state, at rest, its upper part gripped.
  c.name += "-pull-off";
  for (case_file::Body& b : c.bodies) b.velocity.setZero();
  run::with_solver(c.solver.method, [&](auto solver) { hold_for_pull(solver, c, body); });
  c.grip = case_file::Grip{c.bodies[body].name, o.fraction, o.speed * direction,
                           away_from_substrate(impact, body), kRampShare * duration};
  c.solver.end_time = duration;
  c.output.history_interval = duration / 1000.0;
  c.output.snapshot_interval = duration / 4.0;
  c.output.checkpoint_interval = 0.0;
  c.output.probes.clear();
  c.metrics.verdict_extensions = 0;

  run::RunOptions run;
  run.out_dir = o.out / "run";
  run.progress = o.progress;
  run.initial_state = checkpoint;
  run::run_case(c, run);

  // The force on the body from the others along the pull, with its sign turned: positive holds
  // it back.
  const std::string name = c.bodies[body].name;
  const auto columns = io::read_csv_columns(
      o.out / "run" / "history.csv",
      {"time", name + ".contact_fx", name + ".contact_fy", name + ".contact_fz"});
  const double factor = whole_factor(areas, direction);
  for (std::size_t k = 0; k < columns[0].size(); ++k) {
    const Eigen::Vector3d f(columns[1][k], columns[2][k], columns[3][k]);
    r.displacement.push_back(grip_travel(o.speed, c.grip->ramp, columns[0][k]));
    r.force.push_back(-factor * f.dot(direction));
  }
  const auto peak = std::max_element(r.force.begin(), r.force.end());
  r.peak_force = *peak;
  r.peak_displacement = r.displacement[static_cast<std::size_t>(peak - r.force.begin())];
  // The work done against the adhesion: over where the force holds the body back (an impact's
  // splat may start pressed on, pushing the grip before it pulls).
  for (std::size_t k = 1; k < r.force.size(); ++k)
    r.work += 0.5 * (std::max(r.force[k], 0.0) + std::max(r.force[k - 1], 0.0)) *
              (r.displacement[k] - r.displacement[k - 1]);
  r.final_force = r.force.back();
  r.separated = r.peak_force > 0.0 && std::abs(r.final_force) <= kSeparatedShare * r.peak_force;
  write_results(o, r, name, direction);
  if (!areas.points.empty()) write_interface(o.out / "interface.csv", areas);
  return r;
}

}  // namespace coldspray::studies
