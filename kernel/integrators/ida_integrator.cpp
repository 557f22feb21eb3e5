#include "kernel/integrators/ida_integrator.hpp"

#include <ida/ida.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "kernel/integrators/dense_lu_linear_solver.hpp"
#include "kernel/integrators/reforming_linear_solver.hpp"
#include "kernel/integrators/serial_vector.hpp"

namespace heavesim {

IdaIntegrator::~IdaIntegrator() { release(); }

void IdaIntegrator::release() {
  if (ida_) IDAFree(&ida_);
  if (linear_solver_) SUNLinSolFree(linear_solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  for (N_Vector* v : {&y_nv_, &yp_nv_, &id_nv_})
    if (*v) {
      N_VDestroy(*v);
      *v = nullptr;
    }
  ida_ = nullptr;
  linear_solver_ = nullptr;
  matrix_ = nullptr;
}

int IdaIntegrator::residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
  auto* self = static_cast<IdaIntegrator*>(user_data);
  return sundials::guarded(self->callback_error_, [&] {
    self->work_y_ = sundials::map(y);
    self->work_yp_ = sundials::map(yp);
    self->dae_.residual(t, self->work_y_, self->work_yp_, self->work_r_);
    sundials::map(r) = self->work_r_;
  });
}

int IdaIntegrator::error_weights(N_Vector y, N_Vector ewt, void* user_data) {
  // Newton's test weighs the update of every component. A position multiplier's error
  // d moves its constraint Phi over a step h by about h s d
  // (DaeSystem::algebraic_constraint_scales), so its weight is h s /
  // constraint_tolerance: the loops are then closed to the constraint tolerance
  // whatever rtol and atol are, and the weight shrinks with h just as the multiplier's
  // resolution does (the Newton matrix determines it only to O(eps / h), so the ratio of
  // round-off to tolerance, eps |q| / constraint_tolerance, does not depend on h).
  // Multipliers without a scale (lambda) weigh nothing. Any fixed weight is a
  // unit-dependent floor instead: atol 1e-5 on the multipliers made the L1 slider-crank
  // fail at t = 0 for rtol = atol <= 1e-11 and Andrews' mechanism for every rtol < 1e-4
  // in SI but not in mm-g-s; no weight at all let the 3-hour H1 loop drift to
  // |Phi| = 2e-5 m at rtol 1e-4 (with this weight: 3e-11 m, |J v| 7e-12 m/s).
  // (Hairer & Wanner, Solving ODEs II, VII.3, on scaling index-2 algebraic components by
  // h; IDA evaluates the weights once per step, with the step about to be tried.)
  auto* self = static_cast<IdaIntegrator*>(user_data);
  double h = 0.0;
  if (self->ida_) IDAGetCurrentStep(self->ida_, &h);
  const Eigen::Map<VectorX> values = sundials::map(y);
  Eigen::Map<VectorX> weights = sundials::map(ewt);
  const IntegratorSettings& settings = self->settings_;
  const Eigen::Map<VectorX> differential = sundials::map(self->id_nv_);  // 1 differential, 0 algebraic
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (differential[i] > 0.5) {
      weights[i] = 1.0 / (settings.relative_tolerance * std::abs(values[i]) + settings.absolute_tolerance);
    } else {
      const double weight = std::abs(h) * self->constraint_scale_[i] / settings.constraint_tolerance;
      weights[i] = std::max(weight, 1e-100);  // IDA needs positive weights
    }
  }
  return 0;
}

int IdaIntegrator::jacobian(double t, double cj, N_Vector y, N_Vector yp, N_Vector, SUNMatrix J, void* user_data,
                            N_Vector, N_Vector, N_Vector) {
  auto* self = static_cast<IdaIntegrator*>(user_data);
  return sundials::guarded(self->callback_error_, [&] {
    self->work_y_ = sundials::map(y);
    self->work_yp_ = sundials::map(yp);
    self->dae_.jacobian(t, self->work_y_, self->work_yp_, self->residual_y_, self->residual_yp_);
    self->store_newton_matrix(cj, J);
  });
}

void IdaIntegrator::store_newton_matrix(double cj, SUNMatrix J) const {
  const int n = static_cast<int>(residual_y_.rows());
  if (SUNMatGetID(J) == SUNMATRIX_DENSE) {
    for (int c = 0; c < n; ++c)
      Eigen::Map<VectorX>(SUNDenseMatrix_Column(J, c), n) = residual_y_.col(c) + cj * residual_yp_.col(c);
    return;
  }
  // Compressed sparse columns on the pattern fixed at initialization.
  sunindextype* column_start = SUNSparseMatrix_IndexPointers(J);
  sunindextype* row_index = SUNSparseMatrix_IndexValues(J);
  double* values = SUNSparseMatrix_Data(J);
  int k = 0;
  for (int c = 0; c < n; ++c) {
    column_start[c] = k;
    while (k < static_cast<int>(sparsity_.size()) && sparsity_[k].second == c) {
      row_index[k] = sparsity_[k].first;
      values[k] = residual_y_(sparsity_[k].first, c) + cj * residual_yp_(sparsity_[k].first, c);
      ++k;
    }
  }
  column_start[n] = k;
}

int IdaIntegrator::event_functions(double t, N_Vector y, N_Vector, double* g, void* user_data) {
  auto* self = static_cast<IdaIntegrator*>(user_data);
  return sundials::guarded(self->callback_error_, [&] {
    self->work_y_ = sundials::map(y);
    self->dae_.event_values(t, self->work_y_, self->event_values_);
    Eigen::Map<VectorX>(g, self->event_values_.size()) = self->event_values_;
  });
}

void IdaIntegrator::initialize(double t0, const VectorX& y0) {
  state_ = y0;
  before_restarts_ = {};
  events_ = 0;
  dae_.start_events(t0, state_);
  restart(t0);
}

void IdaIntegrator::restart(double t0) {
  release();
  t_ = t0;
  dae_.dae_initial_values(t0, state_, work_y_, work_yp_);  // may fix the DAE's size (kept constraint rows)
  const int n = dae_.dae_size();
  work_r_.resize(n);
  y_nv_ = sundials::new_serial_vector(n, context_);  // IDA's own vectors are its clones
  yp_nv_ = sundials::new_serial_vector(n, context_);
  id_nv_ = sundials::new_serial_vector(n, context_);
  sundials::map(y_nv_) = work_y_;
  sundials::map(yp_nv_) = work_yp_;
  VectorX mask;
  dae_.differential_mask(mask);
  sundials::map(id_nv_) = mask;

  ida_ = IDACreate(context_);
  IDAInit(ida_, &IdaIntegrator::residual, t0, y_nv_, yp_nv_);
  // IDA's warnings go to stderr by default. The one events raise -- an event function
  // still zero after the first step (a stop let go with no speed yet) -- is expected: the
  // function waits until it leaves zero. Errors are still printed, and also reported by
  // the flags (report_failure).
  IDASetErrHandlerFn(
      ida_,
      [](int error_code, const char* module, const char* function, char* message, void*) {
        if (error_code == IDA_WARNING) return;
        std::fprintf(stderr, "\n[%s ERROR]  %s\n  %s\n\n", module, function, message);
      },
      nullptr);
  IDASetUserData(ida_, this);
  // Error weights (error_weights below): the differential components' usual
  // 1 / (rtol |y| + atol); the multipliers take no part in the error test
  // (SuppressAlg) and enter Newton's test with a weight that scales with the step.
  dae_.algebraic_constraint_scales(constraint_scale_);
  IDAWFtolerances(ida_, &IdaIntegrator::error_weights);
  IDASetId(ida_, id_nv_);
  if (mask.minCoeff() < 1.0) IDASetSuppressAlg(ida_, SUNTRUE);  // multipliers: no error test
  IDASetMaxNumSteps(ida_, settings_.max_steps_per_output);
  if (settings_.max_step > 0.0) IDASetMaxStep(ida_, settings_.max_step);

  // The system's own Newton matrix if it has one; its first value fixes the sparsity
  // pattern (with a second look at a nudged state, so that values that happen to be
  // zero here do not drop out of the pattern).
  const bool analytic = dae_.jacobian(t0, work_y_, work_yp_, residual_y_, residual_yp_);
  if (analytic && settings_.linear_solver == LinearSolver::sparse) {
    MatrixX pattern = residual_y_.cwiseAbs() + residual_yp_.cwiseAbs();
    VectorX nudged = work_y_ + 1e-3 * VectorX::Ones(n).cwiseProduct(work_y_.cwiseAbs() + VectorX::Ones(n));
    dae_.jacobian(t0, nudged, work_yp_, residual_y_, residual_yp_);
    pattern += residual_y_.cwiseAbs() + residual_yp_.cwiseAbs();
    sparsity_.clear();
    for (int c = 0; c < n; ++c)
      for (int r = 0; r < n; ++r)
        if (pattern(r, c) != 0.0 || r == c) sparsity_.emplace_back(r, c);
    matrix_ = SUNSparseMatrix(n, n, static_cast<sunindextype>(sparsity_.size()), CSC_MAT, context_);
    linear_solver_ = SUNLinSol_KLU(y_nv_, matrix_, context_);
  } else {
    matrix_ = SUNDenseMatrix(n, n, context_);
    linear_solver_ = sundials::make_dense_lu_linear_solver(matrix_, context_);
  }
  // With position multipliers (loops, drivers, locks, active stops: rows kept in the DAE)
  // the Newton matrix is re-formed from the system's parts when cj moved by more than 30 %
  // from its factor's and after the system refreshed its cheap blocks (reforming_linear_solver.hpp,
  // DaeSystem::refresh_jacobian): on a matrix formed at another cj, or before a loop
  // turned, the multipliers mu converge too slowly for IDA's four iterations
  // (docs/physics/constraints-and-integration.md §5). Slider-crank L1, rtol = atol = 1e-6: 65 convergence failures in 286 steps, 85
  // Jacobian evaluations; re-formed at each cj, 47 in 268; with J's blocks refreshed too,
  // 3 in 175 steps and 18 evaluations (docs/performance.md, "Issue #18, ninth round").
  // Without position multipliers IDA's own policy stays: re-forming turned no convergence
  // failure into a success there, and IDA's acceptance of a first iteration on the old
  // matrix gave the drilling case 6110 steps against 8765.
  const bool position_multipliers = constraint_scale_.size() > 0 && constraint_scale_.maxCoeff() > 0.0;
  const bool reform = analytic && position_multipliers;
  if (reform) {
    const sundials::NewtonMatrixSource source{
        [](void* integrator) {
          double cj = std::numeric_limits<double>::quiet_NaN();  // no cj: the solver re-forms
          IDAGetCurrentCj(static_cast<IdaIntegrator*>(integrator)->ida_, &cj);
          return cj;
        },
        [](void* integrator) {
          auto* self = static_cast<IdaIntegrator*>(integrator);
          return self->dae_.refresh_jacobian(self->residual_y_);  // noexcept
        },
        [](void* integrator, double cj, SUNMatrix matrix) {
          static_cast<IdaIntegrator*>(integrator)->store_newton_matrix(cj, matrix);
        },
        this};
    linear_solver_ = sundials::make_reforming_linear_solver(linear_solver_, source, context_);
  }
  IDASetLinearSolver(ida_, linear_solver_, matrix_);
  if (analytic) IDASetJacFn(ida_, &IdaIntegrator::jacobian);
  // The reforming solver scales a solution for an older cj itself, where it used one.
  if (reform) IDASetLinearSolutionScaling(ida_, SUNFALSE);
  // IDA asks for a new Jacobian when cj has moved out of [0.6, 1.67] of the matrix's (its
  // default dcj = 0.25): its matrix would be stale in cj. The re-forming solver keeps its
  // factor within 30 % of cj, so only the state the parts were taken at ages, which a slow
  // Newton convergence reports (a convergence failure brings a new Jacobian). dcj = 0.9
  // widens the range to [0.053, 19]:
  // the 3-hour H1 run took 851 Jacobians instead of 9405 for 178,176 steps instead of
  // 166,172, at the same accuracy against its 1e-8 reference, CPU 0.86 (docs/performance.md,
  // "Issue #18, fourteenth round"). (Tried before the matrix was re-formed, the wider range
  // cost the slider-crank more failures: its matrix then carried the old cj.)
  if (reform) IDASetDeltaCjLSetup(ida_, 0.9);
  // Events: located where a function falls through zero (a gap closing, a stop's force
  // turning to a pull); one that is zero at t0 waits until it has left zero.
  if (const int count = dae_.event_count(); count > 0) {
    event_values_.resize(count);
    events_found_.assign(count, 0);
    IDARootInit(ida_, count, &IdaIntegrator::event_functions);
    std::vector<int> falling(count, -1);
    IDASetRootDirection(ida_, falling.data());
  }
}

void IdaIntegrator::advance_to(double t_out) {
  if (t_out <= t_) return;
  while (true) {
    double t_reached = t_;
    const int flag = IDASolve(ida_, t_out, &t_reached, y_nv_, yp_nv_, IDA_NORMAL);
    if (flag < 0) report_failure(flag, t_out, t_reached);
    if (flag != IDA_ROOT_RETURN) break;
    // An event at t_reached: the system's handler gives the state to go on from.
    IDAGetRootInfo(ida_, events_found_.data());
    work_y_ = sundials::map(y_nv_);
    dae_.state_from_dae(work_y_, state_);
    ++events_;
    if (dae_.handle_events(t_reached, work_y_, events_found_, state_)) {
      const IntegratorStatistics counts = statistics();
      before_restarts_ = counts;
      before_restarts_.events = 0;
      restart(t_reached);
    }
    t_ = t_reached;
    if (t_reached >= t_out) break;
  }
  t_ = t_out;
  work_y_ = sundials::map(y_nv_);
  dae_.state_from_dae(work_y_, state_);
}

void IdaIntegrator::report_failure(int flag, double t_out, double t_reached) {
  callback_error_.rethrow_if_set();
  double h = 0.0;
  IDAGetLastStep(ida_, &h);
  char reached[96];
  std::snprintf(reached, sizeof reached, ") after reaching t = %.9g s with last step %.3g s", t_reached, h);
  std::string what = std::string("IDA failed (") + sundials::take_flag_name(IDAGetReturnFlagName(flag)) + reached;
  // Where: the differential component with the largest weighted local error of the
  // last step attempted, and what the state looked like there.
  N_Vector errors = N_VClone(y_nv_), weights = N_VClone(y_nv_);
  if (IDAGetEstLocalErrors(ida_, errors) == IDA_SUCCESS && IDAGetErrWeights(ida_, weights) == IDA_SUCCESS)
    what += sundials::largest_local_error(dae_, errors, weights, id_nv_);  // differential components
  N_VDestroy(errors);
  N_VDestroy(weights);
  // The last state IDA reached, examined as the explicit path examines its own: the
  // loops (a driver beyond their reach, a singular configuration), then the fastest
  // mode, which IDA must resolve when it is an excited, barely damped oscillation.
  N_Vector current = nullptr;
  const bool have_state = IDAGetCurrentY(ida_, &current) == IDA_SUCCESS && current;
  const VectorX last_state = have_state ? VectorX(sundials::map(current)) : VectorX();
  const StateDiagnosis note = have_state ? dae_.state_note(t_reached, last_state) : StateDiagnosis{};
  if (!note.empty()) {
    throw NumericalError(t_reached, what + "; " + note.what,
                         !note.suggestion.empty()
                             ? note.suggestion
                             : "the index-2 form cannot resolve the multipliers where the loops lose rank: "
                               "solver.integrator: hht carries a mechanism through singular configurations");
  }
  // Only too much work can be a fast mode's doing: the linearization (an eigenvalue
  // problem) is not done for the other failures.
  const FastestMode mode =
      have_state && flag == IDA_TOO_MUCH_WORK ? dae_.fastest_mode_note(t_reached, last_state) : FastestMode{};
  // About ten steps per period resolve an oscillation at IDA's usual tolerances; the
  // mode is the cause when it alone needs a tenth of the allowed steps.
  const double interval = t_out - t_, omega = std::abs(mode.eigenvalue.imag());
  const double periods = interval * omega / (2.0 * std::numbers::pi), steps_needed = 10.0 * periods;
  if (flag == IDA_TOO_MUCH_WORK && mode.found() && omega >= std::abs(mode.eigenvalue.real()) &&
      steps_needed >= 0.1 * static_cast<double>(settings_.max_steps_per_output)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  ": a barely damped oscillation that IDA resolves, about %.3g of its periods in the output "
                  "interval of %.3g s (solver.max_steps = %ld)",
                  periods, interval, settings_.max_steps_per_output);
    std::string suggestion = "solver.integrator: hht steps over a fast oscillation it need not resolve (A-stable, "
                             "fixed step)";
    if (!mode.element.empty()) suggestion += "; or damp or soften " + mode.element;
    char steps[64];
    std::snprintf(steps, sizeof steps, "; or solver.max_steps above %.3g", steps_needed);
    throw NumericalError(t_reached, what + "; " + mode.description() + text, suggestion + steps);
  }
  std::string suggestion;
  switch (flag) {
    case IDA_TOO_MUCH_WORK:
      suggestion = "the step size collapsed or the output interval is long: raise solver.max_steps or look "
                   "for a stiff or discontinuous force";
      break;
    case IDA_ERR_FAIL:
    case IDA_CONV_FAIL:
      suggestion = "step-size collapse: the solution changes abruptly; loosen tolerances, check force "
                   "elements for discontinuities or unstable parameters, or a singular loop configuration";
      break;
    default:
      suggestion = "check the model for singular configurations or non-finite forces";
  }
  throw NumericalError(t_reached, what, suggestion);
}

IntegratorStatistics IdaIntegrator::statistics() const {
  // The counts of this IDA instance added to those of the instances before the last
  // event restart.
  IntegratorStatistics s = before_restarts_;
  s.events = events_;
  if (!ida_) return s;
  long value = 0;
  const auto add = [](long& total, long count) { total += count; };
  IDAGetNumSteps(ida_, &value), add(s.steps, value);
  IDAGetNumResEvals(ida_, &value), add(s.rhs_evaluations, value);
  IDAGetNumLinResEvals(ida_, &value), add(s.rhs_evaluations, value);
  IDAGetNumJacEvals(ida_, &value), add(s.jacobian_evaluations, value);
  IDAGetNumErrTestFails(ida_, &value), add(s.error_test_failures, value);
  IDAGetNumNonlinSolvIters(ida_, &value), add(s.nonlinear_iterations, value);
  IDAGetNumNonlinSolvConvFails(ida_, &value), add(s.convergence_failures, value);
  IDAGetLastStep(ida_, &s.last_step);
  return s;
}

}  // namespace heavesim
