// `coldspray pull-off IMPACT_DIR`: the numerical pull-off test on an impacted splat
// (studies/pull_off.hpp; docs/pull-off.md).
#include "studies/pull_off.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/path_option.hpp"
#include "cli/quantity_option.hpp"
#include "cli/thread_count.hpp"
#include "core/error.hpp"

namespace coldspray::cli {

void add_pull_off(CLI::App& app) {
  struct Options {
    std::string impact, out, speed = "10 m/s", direction = "normal", distance, body;
    double grip = 0.5;
    bool quiet = false;
    int threads = 0;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = app.add_subcommand(
      "pull-off", "Pull an impacted splat off its substrate and measure its adhesion strength");
  sub->add_option("IMPACT_DIR", opt->impact, "The impact's run folder (its last checkpoint)")
      ->required()
      ->check(given_path());
  sub->add_option("--out", opt->out, "Output folder (default: IMPACT_DIR-pull-off)")
      ->check(given_path());
  sub->add_option("--speed", opt->speed, "The grip's speed after its ramp")->capture_default_str();
  sub->add_option("--direction", opt->direction, "normal (pull-off) or shear (push along x)")
      ->check(CLI::IsMember({"normal", "shear"}))
      ->capture_default_str();
  sub->add_option("--distance", opt->distance,
                  "How far the grip travels (default: three spacings of the splat)");
  sub->add_option("--body", opt->body, "The body to pull (default: the one that moved at t = 0)");
  sub->add_option("--grip", opt->grip, "Share of the body's extent along the pull that is gripped")
      ->capture_default_str();
  sub->add_flag("--quiet", opt->quiet, "No progress line");
  sub->add_option("--threads", opt->threads, "OpenMP threads (default: all cores)")
      ->check(machine_threads());
  sub->callback([opt] {
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    studies::PullOffOptions o;
    o.impact = opt->impact;
    while (o.impact.has_filename() == false && o.impact.has_parent_path())
      o.impact = o.impact.parent_path();  // IMPACT_DIR/ names the folder too
    o.out = opt->out.empty() ? std::filesystem::path(o.impact.string() + "-pull-off")
                             : std::filesystem::path(opt->out);
    o.speed = parse_option_quantity("--speed", opt->speed, units::kVelocity);
    o.shear = opt->direction == "shear";
    if (!opt->distance.empty())
      o.distance = parse_option_quantity("--distance", opt->distance, units::kLength);
    o.body = opt->body;
    o.fraction = opt->grip;
    o.progress = !opt->quiet;
    const studies::PullOffResult r = studies::pull_off(o);
    std::cout << fmt::format(
        "pull-off of {} ({}, {:g} m/s): peak force {:.4g} N at {:.4g} um, work of separation "
        "{:.4g} J\nadhesion strength {:.4g} MPa over the bonded area ({:.4g} um^2), {:.4g} MPa "
        "over the projected area ({:.4g} um^2){}\nresults in {} (summary.json, pull_off.csv; the "
        "run in run/)\n",
        o.impact.string(), opt->direction, o.speed, r.peak_force, r.peak_displacement * 1e6, r.work,
        r.bonded_area > 0.0 ? r.peak_force / r.bonded_area * 1e-6 : 0.0, r.bonded_area * 1e12,
        r.projected_area > 0.0 ? r.peak_force / r.projected_area * 1e-6 : 0.0,
        r.projected_area * 1e12,
        r.separated ? ""
                    : "\nwarning: the force had not fallen back to 1 % of its peak at the end: "
                      "pull further (--distance)",
        o.out.string());
  });
}

}  // namespace coldspray::cli
