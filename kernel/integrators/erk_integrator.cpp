#include "kernel/integrators/erk_integrator.hpp"

#include <arkode/arkode_erkstep.h>

#include <cstdio>
#include <optional>
#include <string>

#include "kernel/integrators/explicit_stability.hpp"
#include "kernel/integrators/serial_vector.hpp"

namespace heavesim {

ErkIntegrator::ErkIntegrator(OdeSystem& system, const IntegratorSettings& settings, ARKODE_ERKTableID table)
    : settings_(settings), table_(table), system_(system) {
  ARKodeButcherTable loaded = ARKodeButcherTable_LoadERK(table);
  if (loaded) {
    tableau_.stages = loaded->stages;
    tableau_.a.resize(loaded->stages * loaded->stages);
    tableau_.b.assign(loaded->b, loaded->b + loaded->stages);
    for (int i = 0; i < loaded->stages; ++i)
      for (int j = 0; j < loaded->stages; ++j) tableau_.a[i * loaded->stages + j] = loaded->A[i][j];
    ARKodeButcherTable_Free(loaded);
  }
}

ErkIntegrator::~ErkIntegrator() { release(); }

void ErkIntegrator::release() {
  if (arkode_) ERKStepFree(&arkode_);
  if (y_nv_) N_VDestroy(y_nv_);
  arkode_ = nullptr;
  y_nv_ = nullptr;
}

int ErkIntegrator::rhs(double t, N_Vector y, N_Vector ydot, void* user_data) {
  auto* self = static_cast<ErkIntegrator*>(user_data);
  return sundials::guarded(self->callback_error_, [&] {
    self->work_y_ = sundials::map(y);
    self->system_.derivative(t, self->work_y_, self->work_f_);
    sundials::map(ydot) = self->work_f_;
  });
}

int ErkIntegrator::project_step(double t, N_Vector y, void* user_data) {
  auto* self = static_cast<ErkIntegrator*>(user_data);
  return sundials::guarded(self->callback_error_, [&] {
    self->work_y_ = sundials::map(y);
    self->system_.project(t, self->work_y_);
    sundials::map(y) = self->work_y_;
  });
}

void ErkIntegrator::initialize(double t0, const VectorX& y0) {
  release();
  t_ = t0;
  y_ = y0;
  const int n = system_.size();
  work_y_.resize(n);
  work_f_.resize(n);
  y_nv_ = sundials::new_serial_vector(n, context_);  // ARKODE's own vectors are its clones
  sundials::map(y_nv_) = y0;
  arkode_ = ERKStepCreate(&ErkIntegrator::rhs, t0, y_nv_, context_);
  ERKStepSetUserData(arkode_, this);
  ERKStepSetTableNum(arkode_, table_);
  ERKStepSStolerances(arkode_, settings_.relative_tolerance, settings_.absolute_tolerance);
  ERKStepSetMaxNumSteps(arkode_, settings_.max_steps_per_output);
  if (settings_.max_step > 0.0) ERKStepSetMaxStep(arkode_, settings_.max_step);
  ERKStepSetPostprocessStepFn(arkode_, &ErkIntegrator::project_step);
}

void ErkIntegrator::advance_to(double t_out) {
  if (t_out <= t_) return;
  double t_reached = t_;
  ERKStepSetStopTime(arkode_, t_out);
  const int flag = ERKStepEvolve(arkode_, t_out, y_nv_, &t_reached, ARK_NORMAL);
  if (flag < 0) fail(flag, t_out, t_reached);
  t_ = t_out;
  y_ = sundials::map(y_nv_);  // the last step ended on t_out and was projected
}

void ErkIntegrator::fail(int flag, double t_out, double t_reached) {
  // An evaluation's own error (an element out of its range, a singular loop) is the
  // first candidate; the fastest mode can overrule it below.
  std::optional<NumericalError> evaluation_error;
  try {
    callback_error_.rethrow_if_set();
  } catch (const NumericalError& error) {
    evaluation_error = error;
  }
  double h = 0.0;
  ERKStepGetCurrentStep(arkode_, &h);
  char reached[96];
  std::snprintf(reached, sizeof reached, ") at t = %.9g s with step %.3g s", t_reached, h);
  std::string what = std::string("ARKODE ERK failed (") + sundials::take_flag_name(ERKStepGetReturnFlagName(flag)) + reached;
  // The fastest mode at the last accepted state (returned in y_nv_): beyond the
  // stability limit it explains any symptom; with too much work, it explains the step
  // count when it alone needs a tenth of the allowed steps at the stability limit (a
  // discontinuity or a singular loop needs only a few short steps).
  const VectorX last_state = sundials::map(y_nv_);
  const FastestMode mode = system_.fastest_mode_note(t_reached, last_state);
  if (mode.found()) {
    const double limit = stability_limit(tableau_, mode.eigenvalue);
    const double steps_needed = (t_out - t_) / limit;
    const std::string method = integration_method_name(settings_.method);
    if (h > limit)
      throw beyond_stability_limit(t_reached, method, h, limit, mode,
                                   evaluation_error ? evaluation_error->what() : what);
    if (flag == ARK_TOO_MUCH_WORK && steps_needed >= 0.1 * static_cast<double>(settings_.max_steps_per_output)) {
      char text[240];
      std::snprintf(text, sizeof text,
                    ": it holds the explicit step below %s's stability limit of %.3g s, and the output interval of "
                    "%.3g s needs at least %.3g such steps (solver.max_steps = %ld)",
                    method.c_str(), limit, t_out - t_, steps_needed, settings_.max_steps_per_output);
      throw NumericalError(t_reached, what + "; " + mode.description() + text,
                           fast_mode_remedy(mode, steps_needed));
    }
  }
  if (evaluation_error) throw *evaluation_error;
  // Where: the component with the largest weighted local error of the last attempt,
  // and what the last accepted state looked like.
  N_Vector errors = N_VClone(y_nv_), weights = N_VClone(y_nv_);
  if (ERKStepGetEstLocalErrors(arkode_, errors) == ARK_SUCCESS && ERKStepGetErrWeights(arkode_, weights) == ARK_SUCCESS)
    what += sundials::largest_local_error(system_, errors, weights);
  N_VDestroy(errors);
  N_VDestroy(weights);
  const StateDiagnosis note = system_.state_note(t_reached, last_state);
  throw note.explain(t_reached, what,
                     !note.empty() ? "solver.integrator: hht carries a mechanism through singular configurations"
                     : flag == ARK_TOO_MUCH_WORK
                         ? "too many steps: the problem may be stiff (use solver.integrator: ida) or "
                           "solver.max_steps too low for the output interval"
                         : "step-size collapse at that component: look for a discontinuous or "
                           "unstable force element acting there, or loosen the tolerances");
}

IntegratorStatistics ErkIntegrator::statistics() const {
  IntegratorStatistics s;
  if (!arkode_) return s;
  long attempts = 0;
  ERKStepGetNumSteps(arkode_, &s.steps);
  ERKStepGetNumRhsEvals(arkode_, &s.rhs_evaluations);
  ERKStepGetNumErrTestFails(arkode_, &s.error_test_failures);
  ERKStepGetNumStepAttempts(arkode_, &attempts);
  ERKStepGetLastStep(arkode_, &s.last_step);
  return s;
}

}  // namespace heavesim
