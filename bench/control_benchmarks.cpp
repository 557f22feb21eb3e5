// Stiffness of the hydraulic active compensator: the C2 case on the H0 rig with the
// servo-valve-driven cylinder (cases/c2_prescribed_heave/h0_active_hydraulic.yaml),
// 60 s, integrated by IDA (BDF, implicit) and by Dormand-Prince (explicit) at the same
// tolerances, for servo valves of 10 to 300 Hz. The valve's spool is the stiffest
// state (eigenvalues ~ -w_v (zeta +- i sqrt(1 - zeta^2))): the explicit method's step
// is capped by its stability limit ~3.3 / w_v, so its step count grows with the valve
// frequency; IDA's steps follow the accuracy asked for and hardly change. Counters:
// steps, residual / right-hand-side evaluations, efficiency of the run (it must not
// depend on the method). Run: build/bench/heavesim_control_bench.
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"

namespace heavesim::bench {
namespace {

constexpr const char* case_path = HEAVESIM_SOURCE_DIR "/cases/c2_prescribed_heave/h0_active_hydraulic.yaml";

void hydraulic_c2(benchmark::State& state) {
  const bool implicit = state.range(0) == 0;
  const double valve_hz = static_cast<double>(state.range(1));
  const CaseDefinition definition =
      load_case(case_path, {"solver.t_end=60", "solver.rtol=1e-5", "solver.atol=1e-5", "output.interval=0.1",
                            implicit ? "solver.integrator=ida" : "solver.integrator=dopri5",
                            fmt::format("forces[active].actuator.valve.natural_frequency=2*pi*{}", valve_hz)});
  IntegratorStatistics statistics;
  double min_crown = 1e300, max_crown = -1e300;
  for (auto _ : state) {
    Scene scene = build_scene(definition);
    std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
    const int crown = scene.model->link_index("crown");
    min_crown = 1e300, max_crown = -1e300;
    const RunOutcome outcome =
        run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
          if (t >= 40.0) {
            scene.system->evaluate(t, y, false);
            const double z = scene.system->data().X_world_link[crown].translation().z();
            min_crown = std::min(min_crown, z);
            max_crown = std::max(max_crown, z);
          }
          return true;
        });
    statistics = outcome.statistics;
  }
  state.SetLabel(fmt::format("{} valve {:g} Hz", implicit ? "IDA" : "Dormand-Prince", valve_hz));
  state.counters["steps"] = static_cast<double>(statistics.steps);
  state.counters["evaluations"] = static_cast<double>(statistics.rhs_evaluations);
  state.counters["efficiency"] = 1.0 - 0.5 * (max_crown - min_crown);  // platform heave amplitude 1 m
}

BENCHMARK(hydraulic_c2)
    ->ArgsProduct({{0, 1}, {10, 30, 100, 300}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
