#include "kernel/integrators/ida_integrator.hpp"

#include <ida/ida.h>

#include <string>

namespace heavesim {

IdaIntegrator::~IdaIntegrator() { release(); }

void IdaIntegrator::release() {
  if (ida_) IDAFree(&ida_);
  if (linear_solver_) SUNLinSolFree(linear_solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  if (y_nv_) N_VDestroy(y_nv_);
  if (yp_nv_) N_VDestroy(yp_nv_);
  ida_ = nullptr;
  linear_solver_ = nullptr;
  matrix_ = nullptr;
  y_nv_ = yp_nv_ = nullptr;
}

int IdaIntegrator::residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
  auto* self = static_cast<IdaIntegrator*>(user_data);
  const int flag =
      sundials::evaluate_derivative(*self->system_, t, y, self->work_y_, self->work_f_, self->callback_error_);
  if (flag == 0) sundials::map(r) = sundials::map(yp) - self->work_f_;
  return flag;
}

void IdaIntegrator::initialize(OdeSystem& system, double t0, const VectorX& y0) {
  release();
  system_ = &system;
  t_ = t0;
  y_ = y0;
  const int n = system.size();
  work_y_.resize(n);
  work_f_.resize(n);
  y_nv_ = N_VNew_Serial(n, context_);
  yp_nv_ = N_VNew_Serial(n, context_);
  sundials::map(y_nv_) = y0;
  work_y_ = y0;
  system.derivative(t0, work_y_, work_f_);
  sundials::map(yp_nv_) = work_f_;

  ida_ = IDACreate(context_);
  IDAInit(ida_, &IdaIntegrator::residual, t0, y_nv_, yp_nv_);
  IDASetUserData(ida_, this);
  IDASStolerances(ida_, settings_.relative_tolerance, settings_.absolute_tolerance);
  matrix_ = SUNDenseMatrix(n, n, context_);
  linear_solver_ = SUNLinSol_Dense(y_nv_, matrix_, context_);
  IDASetLinearSolver(ida_, linear_solver_, matrix_);
  IDASetMaxNumSteps(ida_, settings_.max_steps_per_output);
  if (settings_.max_step > 0.0) IDASetMaxStep(ida_, settings_.max_step);
}

void IdaIntegrator::advance_to(double t_out) {
  if (t_out <= t_) return;
  double t_reached = t_;
  const int flag = IDASolve(ida_, t_out, &t_reached, y_nv_, yp_nv_, IDA_NORMAL);
  if (flag < 0) {
    callback_error_.rethrow_if_set();
    double h = 0.0;
    IDAGetLastStep(ida_, &h);
    std::string what = std::string("IDA failed (") + IDAGetReturnFlagName(flag) + ") after reaching t = " +
                       std::to_string(t_reached) + " s with last step " + std::to_string(h) + " s";
    std::string suggestion;
    switch (flag) {
      case IDA_TOO_MUCH_WORK:
        suggestion = "the step size collapsed or the output interval is long: raise solver.max_steps or look "
                     "for a stiff or discontinuous force";
        break;
      case IDA_ERR_FAIL:
      case IDA_CONV_FAIL:
        suggestion = "step-size collapse: the solution changes abruptly; loosen tolerances, check force "
                     "elements for discontinuities or unstable parameters";
        break;
      default:
        suggestion = "check the model for singular configurations or non-finite forces";
    }
    throw NumericalError(t_reached, what, suggestion);
  }
  t_ = t_out;
  y_ = sundials::map(y_nv_);
  system_->project(t_, y_);
}

IntegratorStatistics IdaIntegrator::statistics() const {
  IntegratorStatistics s;
  if (!ida_) return s;
  long value = 0;
  IDAGetNumSteps(ida_, &s.steps);
  IDAGetNumResEvals(ida_, &s.rhs_evaluations);
  IDAGetNumLinResEvals(ida_, &value);
  s.rhs_evaluations += value;
  IDAGetNumJacEvals(ida_, &s.jacobian_evaluations);
  IDAGetNumErrTestFails(ida_, &s.error_test_failures);
  IDAGetNumNonlinSolvIters(ida_, &s.nonlinear_iterations);
  IDAGetNumNonlinSolvConvFails(ida_, &s.convergence_failures);
  IDAGetLastStep(ida_, &s.last_step);
  return s;
}

}  // namespace heavesim
