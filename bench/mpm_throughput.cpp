// MPM throughput in particle-steps per second on the impact: a 14 um Al sphere on a
// 30 um x 10 um Al cylinder at 810 m/s with al-ptw (examples/al-14um-810.yaml), in 3D at
// 1.0 um cells / 0.25 um spacing (linear and GIMP) and axisymmetric at 0.7 / 0.175.
// Each case first runs into the impact (contact and plasticity active), then times steps.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <string>
#include <vector>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace {

using namespace coldspray;

void impact(benchmark::State& bench, const std::string& geometry, const std::string& shape,
            const std::string& cell, const std::string& spacing) {
  const std::vector<case_file::Override> overrides = {{"solver.geometry", geometry},
                                                      {"solver.shape_function", shape},
                                                      {"grid.cell_size", cell},
                                                      {"bodies.particle.spacing", spacing},
                                                      {"bodies.substrate.spacing", spacing}};
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/al-14um-810.yaml", overrides);
  mpm::State s = mpm::build_state(c);
  auto advance = [&] {
    s.dt = mpm::stable_time_step(s, c.solver.cfl);
    mpm::step(s);
  };
  while (s.time < 5e-9) advance();  // into the impact
  for (auto _ : bench) advance();
  bench.counters["particles"] = static_cast<double>(s.points.size());
  bench.counters["threads"] = omp_get_max_threads();
  bench.counters["particle_steps_per_second"] = benchmark::Counter(
      static_cast<double>(s.points.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void Impact3dLinear(benchmark::State& b) { impact(b, "3d", "linear", "1.0 um", "0.25 um"); }
void Impact3dGimp(benchmark::State& b) { impact(b, "3d", "gimp", "1.0 um", "0.25 um"); }
void ImpactAxisymmetricGimp(benchmark::State& b) {
  impact(b, "axisymmetric", "gimp", "0.7 um", "0.175 um");
}
void ImpactAxisymmetricLinear(benchmark::State& b) {
  impact(b, "axisymmetric", "linear", "0.7 um", "0.175 um");
}

BENCHMARK(Impact3dLinear)->Unit(benchmark::kMillisecond)->MinTime(5.0)->UseRealTime();
BENCHMARK(Impact3dGimp)->Unit(benchmark::kMillisecond)->MinTime(5.0)->UseRealTime();
BENCHMARK(ImpactAxisymmetricGimp)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(ImpactAxisymmetricLinear)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
