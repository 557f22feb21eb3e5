#pragma once
// The integration loop shared by `heavesim run` and the validation suite.
#include <functional>
#include <memory>

#include "app/case/case_definition.hpp"
#include "app/scene/scene.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim {

/// Called at t_start and at every output time; return false to stop early.
using Observer = std::function<bool(double t, const VectorX& y)>;

struct RunOutcome {
  bool completed = false;     // reached t_end
  double time_reached = 0.0;  // s
  IntegratorStatistics statistics;
};

/// Integrates the scene from solver.t_start to solver.t_end, observing every
/// output interval (the last sample lands exactly on t_end). NumericalError
/// propagates; `integrator` keeps the state reached.
RunOutcome run_simulation(Scene& scene, const SolverSettings& solver, double output_interval,
                          Integrator& integrator, const Observer& observe);

}  // namespace heavesim
