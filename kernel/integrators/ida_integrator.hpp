#pragma once
#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "kernel/integrators/integrator.hpp"
#include "kernel/integrators/sundials_support.hpp"
#include "kernel/system/dae_system.hpp"

namespace heavesim {

/// SUNDIALS IDA (variable-order, variable-step BDF) on a DaeSystem: a multibody
/// model's stabilized index-2 form (GglDaeForm, with its algebraic multipliers excluded
/// from the error test), or a plain ODE written as F = y' - f(t, y) (OdeResidual). Newton matrices come from the system when it
/// provides them (dense, or sparse through KLU), else from IDA's difference quotients.
/// Suited to stiff force elements (hydraulics, end stops) and closed loops. Events of the
/// system (DaeSystem::event_count: joint stops) are located by IDA's root finding; at
/// each, the system's handler gives the state to restart from.
class IdaIntegrator : public Integrator {
 public:
  IdaIntegrator(DaeSystem& system, const IntegratorSettings& settings) : settings_(settings), dae_(system) {}
  ~IdaIntegrator() override;
  void initialize(double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return state_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override;

 private:
  static int residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data);
  static int event_functions(double t, N_Vector y, N_Vector yp, double* g, void* user_data);
  /// IDA set up afresh at (t0, state_) (the start, or after an event changed the state).
  void restart(double t0);
  /// Throws the NumericalError of a failed IDASolve (flag < 0) on the way to t_out.
  [[noreturn]] void report_failure(int flag, double t_out, double t_reached);
  static int error_weights(N_Vector y, N_Vector ewt, void* user_data);
  static int jacobian(double t, double cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void* user_data,
                      N_Vector, N_Vector, N_Vector);
  void release();
  /// Writes dF/dy + cj dF/dy' of the last evaluation into J (dense, or the fixed sparsity
  /// pattern of KLU).
  void store_newton_matrix(double cj, SUNMatrix J) const;

  IntegratorSettings settings_;
  DaeSystem& dae_;
  sundials::Context context_;
  sundials::CallbackError callback_error_;
  void* ida_ = nullptr;
  N_Vector y_nv_ = nullptr, yp_nv_ = nullptr, id_nv_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_solver_ = nullptr;
  VectorX state_, work_y_, work_yp_, work_r_;
  VectorX constraint_scale_;  // DaeSystem::algebraic_constraint_scales
  MatrixX residual_y_, residual_yp_;  // dF/dy and dF/dy' of the last evaluation (DaeSystem::jacobian)
  std::vector<std::pair<int, int>> sparsity_;  // (row, column) kept by the sparse matrix, column-major order
  std::vector<int> events_found_;             // IDAGetRootInfo
  VectorX event_values_;
  IntegratorStatistics before_restarts_;      // the counts of the IDA instances an event ended
  long events_ = 0;
  double t_ = 0.0;
};

}  // namespace heavesim
