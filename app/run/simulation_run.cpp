#include "app/run/simulation_run.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim {

namespace {
long output_intervals(const SolverSettings& solver, double output_interval) {
  return std::max(1L, std::lround((solver.t_end - solver.t_start) / output_interval));
}
}  // namespace

long output_sample_count(const SolverSettings& solver, double output_interval) {
  return output_intervals(solver, output_interval) + 1;
}

RunOutcome run_simulation(Scene& scene, const SolverSettings& solver, double output_interval,
                          Integrator& integrator, const Observer& observe) {
  const long intervals = output_intervals(solver, output_interval);
  RunOutcome outcome;
  integrator.initialize(solver.t_start, scene.initial_state);
  outcome.time_reached = solver.t_start;
  bool go_on = observe(solver.t_start, integrator.state());
  for (long k = 1; k <= intervals && go_on; ++k) {
    const double t = k == intervals ? solver.t_end : solver.t_start + k * output_interval;
    integrator.advance_to(t);
    outcome.time_reached = t;
    go_on = observe(t, integrator.state());
  }
  outcome.completed = outcome.time_reached >= solver.t_end;
  outcome.statistics = integrator.statistics();
  return outcome;
}

}  // namespace heavesim
