// `coldspray impact`: one particle on a substrate from a few options. Builds the thesis'
// particle-on-cylinder case (setups/impact_case.hpp), validates it like a case file, runs it and
// prints the verdict on the particle's last window of motion (docs/bonding.md); or writes the case
// out to be edited.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "cli/commands.hpp"
#include "cli/impact_options.hpp"
#include "cli/path_option.hpp"
#include "cli/run_report.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "setups/impact_case.hpp"

namespace coldspray::cli {

namespace {

// What names the generated case in messages that no option accounts for.
constexpr const char* kSource = "coldspray impact";

struct ImpactCommandOptions {
  ImpactCaseOptions impact;
  std::string diameter, velocity, write_case;
  RunFlags run;
};

setups::ImpactSpec make_spec(const ImpactCommandOptions& o, const CLI::App& sub) {
  return impact_spec(
      o.impact, parse_diameter("--diameter", o.diameter), parse_speed("--velocity", o.velocity),
      command_line(kSource, sub, {"--write-case", "--out", "--overwrite", "--threads", "--quiet"}));
}

// The case file to write: the generated text, or with --set its tree after the overrides
// (which loses the comments but the header's).
std::string case_file_text(const setups::GeneratedCase& g,
                           const std::vector<case_file::Override>& overrides) {
  if (overrides.empty()) return g.yaml;
  std::string header;
  for (std::size_t start = 0; start < g.yaml.size() && g.yaml[start] == '#';) {
    const std::size_t end = g.yaml.find('\n', start) + 1;
    header += g.yaml.substr(start, end - start);
    start = end;
  }
  header += "# Then edited by the --set options above (which the other comments predate).\n";
  return header + case_file::apply_overrides(kSource, g.yaml, overrides);
}

void write_case(const std::string& path, const std::string& text) {
  io::require_writable(path, "--write-case");
  io::write_atomically(path, [&](std::ostream& out) { out << text; });
}

std::string speed_text(double v) {
  return std::isnan(v) ? std::string("undefined") : fmt::format("{:.3g} m/s", v);
}

// The particle's verdict (docs/bonding.md, "The verdict") with the numbers it rests on, and its
// impact measures.
void print_verdict(const case_file::Case& c, const run::Summary& s, std::ostream& out) {
  auto body = [&s](const char* name) {
    return std::find_if(s.bodies.begin(), s.bodies.end(),
                        [name](const auto& b) { return b.name == name; });
  };
  const auto particle = body("particle"), substrate = body("substrate");
  if (particle == s.bodies.end() || !particle->verdict) return;  // renamed or stopped by --set
  const metrics::Verdict& v = *particle->verdict;
  std::string outcome(metrics::outcome_name(v.outcome));
  std::transform(outcome.begin(), outcome.end(), outcome.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  if (s.extensions > 0)
    outcome += fmt::format(" after {} extension{} to {:.4g} ns", s.extensions,
                           s.extensions == 1 ? "" : "s", s.time * 1e9);
  std::string why =
      fmt::format("mean separation speed {} over the last {:.3g} ns, margin {}",
                  speed_text(v.separation_speed), v.window * 1e9, speed_text(v.margin));
  if (v.outcome == metrics::Outcome::Undecided)
    why += fmt::format(", its halves {} apart", speed_text(std::abs(v.settling)));
  why += fmt::format("; bonded area {:.3g} um^2", v.bonded_area * 1e12);
  if (c.contact.peridynamics.model != case_file::ContactModel::Repulsive)
    why = "the adhesive contact's hold: the bonded area is the particle's points it holds; " + why;
  else if (c.bonding.model == case_file::BondingModel::None)
    why = "bonding model none: nothing bonds; " + why;
  out << fmt::format("verdict: {} ({})\n", outcome, why);
  const metrics::ImpactMeasures& m = particle->impact;
  out << fmt::format(
      "  cor {:.3g}, v_rest {}, pbcp {:.3g} %, jetted {:.3g} % of the particle's mass", m.cor,
      speed_text(m.v_rest), m.pbcp, 100.0 * m.jetted_fraction);
  if (substrate != s.bodies.end())
    out << fmt::format(", crater depth {:.3g} um", substrate->impact.crater_depth * 1e6);
  out << "\n";
  if (c.bonding.model != case_file::BondingModel::None && c.bonding.critical_penetration > 0.0)
    out << fmt::format(
        "  penetration {:.4g} of its size, {} the critical {:.4g} (bonding.critical_penetration)\n",
        m.penetration, m.penetration >= c.bonding.critical_penetration ? "reaching" : "short of",
        c.bonding.critical_penetration);
}

}  // namespace

void add_impact(CLI::App& app) {
  auto opt = std::make_shared<ImpactCommandOptions>();
  auto* sub = app.add_subcommand(
      "impact",
      "Run the thesis' single-particle test: a sphere hitting a cylindrical substrate at first "
      "contact (docs/impact.md)");
  add_impact_case_options(*sub, opt->impact, [&] {
    sub->add_option("--diameter", opt->diameter, "Particle diameter, e.g. 22um")->required();
    sub->add_option("--velocity", opt->velocity, "Impact speed, e.g. 790m/s")->required();
  });
  sub->add_option("--write-case", opt->write_case,
                  "Write the case file and stop (edit it, then `coldspray run` it)")
      ->check(given_path());
  add_run_flags(*sub, opt->run);
  sub->callback([opt, sub] {
    const setups::ImpactSpec spec = make_spec(*opt, *sub);
    const setups::GeneratedCase g = setups::impact_case(spec);
    const std::vector<case_file::Override> overrides = parse_overrides(opt->run.sets);
    const case_file::Case c = case_file::load_case_text(kSource, g.yaml, g.origins, overrides);
    // After the case is read: a refused command's output is its error, not a warning about the
    // calibration of a pair that is not simulated (an unknown --material).
    if (const std::string w = calibration_warning(opt->impact); !w.empty()) std::cerr << w << "\n";
    if (!opt->write_case.empty()) {
      write_case(opt->write_case, case_file_text(g, overrides));
      std::cout << fmt::format("wrote {} (run it with: coldspray run {})\n", opt->write_case,
                               shell_quoted(opt->write_case));
      return;
    }
    const Report report = run_and_report(c, opt->run, std::cout);
    print_verdict(c, report.summary, std::cout);
    print_results_location(report.out_dir, std::cout);
  });
}

}  // namespace coldspray::cli
