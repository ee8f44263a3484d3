// Peridynamics throughput on the PD paper's impact: a 30 um cu-jc particle at 500 m/s on a
// cu-jc cylinder of radius and height 60 um, one quarter (the case `coldspray impact --solver
// peridynamics` writes), at D/25 and D/50 spacing. Each case first runs into the impact
// (contact and plasticity active), then times steps. Reports point-steps/s, bond-steps/s (bonds
// = neighbour pairs visited per step, each family member once) and the families' bytes per bond.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <string>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"
#include "setups/impact_case.hpp"

namespace {

using namespace coldspray;

void impact(benchmark::State& bench, double points_across) {
  setups::ImpactSpec spec;
  spec.solver = case_file::Method::Peridynamics;
  spec.material = "cu-jc";
  spec.diameter = 30e-6;
  spec.speed = 500.0;
  spec.geometry = case_file::Geometry::ThreeD;
  spec.bonding = "none";
  spec.spacing = spec.diameter / points_across;
  spec.command = "bench/pd_throughput";
  const setups::GeneratedCase g = setups::impact_case(spec);
  const case_file::Case c = case_file::load_case_text(g.name + ".yaml", g.yaml, {}, {});
  pd::State s = pd::build_state(c);
  auto advance = [&] {
    s.dt = pd::stable_time_step(s, c.solver.cfl);
    pd::step(s);
  };
  while (s.time < 2e-9) advance();  // into the impact
  for (auto _ : bench) advance();
  const double bonds = static_cast<double>(s.families.bonds());
  const double bytes = bonds * (sizeof(std::uint32_t) + sizeof(std::uint16_t)) +
                       static_cast<double>(s.families.begin.size() * sizeof(std::size_t));
  bench.counters["points"] = static_cast<double>(s.points.size());
  bench.counters["ghosts"] = static_cast<double>(s.ghosts.size());
  bench.counters["bonds"] = bonds;
  bench.counters["bytes_per_bond"] = bytes / bonds;
  bench.counters["pair_blocks"] = static_cast<double>(s.pairs.block.size() - 1);
  bench.counters["threads"] = omp_get_max_threads();
  bench.counters["point_steps_per_second"] = benchmark::Counter(
      static_cast<double>(s.points.size()), benchmark::Counter::kIsIterationInvariantRate);
  bench.counters["bond_steps_per_second"] =
      benchmark::Counter(bonds, benchmark::Counter::kIsIterationInvariantRate);
}

void PdImpactD25(benchmark::State& b) { impact(b, 25.0); }
void PdImpactD50(benchmark::State& b) { impact(b, 50.0); }

BENCHMARK(PdImpactD25)->Unit(benchmark::kMillisecond)->MinTime(5.0)->UseRealTime();
BENCHMARK(PdImpactD50)->Unit(benchmark::kMillisecond)->MinTime(10.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
