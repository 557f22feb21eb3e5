#include "app/run/simulation_run.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim {

RunOutcome run_simulation(Scene& scene, const SolverSettings& solver, double output_interval,
                          Integrator& integrator, const Observer& observe) {
  const long intervals = output_interval_count(solver, output_interval);
  RunOutcome outcome;
  integrator.initialize(solver.t_start, scene.initial_state);
  outcome.time_reached = solver.t_start;
  // An output evaluates the state the integrator returned: a failure there is the
  // integrator's to explain (an explicit step beyond its stability limit).
  const auto observe_state = [&](double t) {
    try {
      return observe(t, integrator.state());
    } catch (const NumericalError& error) {
      throw integrator.explain(error);
    }
  };
  bool go_on = observe_state(solver.t_start);
  for (long k = 1; k <= intervals && go_on; ++k) {
    const double t = k == intervals ? solver.t_end : solver.t_start + k * output_interval;
    integrator.advance_to(t);
    outcome.time_reached = t;
    go_on = observe_state(t);
  }
  outcome.completed = outcome.time_reached >= solver.t_end;
  outcome.statistics = integrator.statistics();
  return outcome;
}

}  // namespace heavesim
