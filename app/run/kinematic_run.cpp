#include "app/run/kinematic_run.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace heavesim {
namespace {

/// The failure of the position solve at t: the rows being lost and the drivers among
/// them (MultibodySystem::constraint_loss) at the last Newton iterate.
NumericalError unreachable_position(MultibodySystem& system, double t, const KinematicPoint& point,
                                    const KinematicSettings& settings) {
  const StateDiagnosis loss = system.constraint_loss(t, 1.0);
  std::string what = fmt::format("the position at t = {:.6g} s cannot be reached: max |Phi| = {:.3g} after {} Newton "
                                 "iterations (kinematics.equation_tolerance {:g}, solution_tolerance {:g}; last "
                                 "step {:.3g})",
                                 t, point.equation_residual, point.newton_iterations, settings.equation_tolerance,
                                 settings.solution_tolerance, point.last_step);
  return loss.explain(t, what,
                      "the drivers ask for a position the mechanism cannot take (beyond a loop's reach or "
                      "through a dead centre): check the drivers' position expressions and the loop "
                      "geometry; a finer output.interval helps only where the motion is fast between "
                      "samples");
}

}  // namespace

KinematicOutcome run_kinematics(Scene& scene, const CaseDefinition& definition, bool compute_reactions,
                                const KinematicObserver& observe) {
  const Model& model = *scene.model;
  MultibodySystem& system = *scene.system;
  const SolverSettings& solver = definition.solver;
  const KinematicSettings& settings = definition.kinematics;
  const long intervals = output_interval_count(solver, definition.output.interval);
  KinematicWorkspace workspace(model);
  VectorX y = scene.initial_state;
  VectorX q = y.head(model.nq), v = y.segment(model.nq, model.nv), a = VectorX::Zero(model.nv);
  KinematicOutcome outcome;
  outcome.time_reached = solver.t_start;
  double previous_t = solver.t_start;
  for (long k = 0; k <= intervals; ++k) {
    const double t =
        k == 0 ? solver.t_start : (k == intervals ? solver.t_end : solver.t_start + k * definition.output.interval);
    const KinematicPoint point =
        analyse_time_point(model, system.mutable_data(), workspace, settings, t, t - previous_t, q, v, a);
    if (!point.converged) throw unreachable_position(system, t, point, settings);
    previous_t = t;
    y.head(model.nq) = q;
    y.segment(model.nq, model.nv) = v;
    system.evaluate_prescribed(t, y, a, compute_reactions);
    ++outcome.points;
    outcome.time_reached = t;
    outcome.newton_iterations += point.newton_iterations;
    outcome.max_equation_residual = std::max(outcome.max_equation_residual, point.equation_residual);
    outcome.smallest_singular_ratio = std::min(outcome.smallest_singular_ratio, point.singular_ratio);
    if (model.nv > 0)
      outcome.max_dynamic_residual =
          std::max(outcome.max_dynamic_residual, system.dynamic_residual().cwiseAbs().maxCoeff());
    if (!observe(t, y, point)) break;
  }
  outcome.completed = outcome.time_reached >= solver.t_end;
  return outcome;
}

}  // namespace heavesim
