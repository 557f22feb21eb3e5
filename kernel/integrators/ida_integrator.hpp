#pragma once
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "kernel/integrators/integrator.hpp"
#include "kernel/integrators/sundials_support.hpp"

namespace heavesim {

/// SUNDIALS IDA (variable-order, variable-step BDF) on the ODE written as the
/// residual F(t, y, y') = y' - f(t, y), with a dense direct linear solver and IDA's
/// difference-quotient Jacobian. Suited to stiff force elements (hydraulics, end stops).
class IdaIntegrator : public Integrator {
 public:
  explicit IdaIntegrator(const IntegratorSettings& settings) : settings_(settings) {}
  ~IdaIntegrator() override;
  void initialize(OdeSystem& system, double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return y_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override;

 private:
  static int residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data);
  void release();

  IntegratorSettings settings_;
  OdeSystem* system_ = nullptr;
  sundials::Context context_;
  sundials::CallbackError callback_error_;
  void* ida_ = nullptr;
  N_Vector y_nv_ = nullptr, yp_nv_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_solver_ = nullptr;
  VectorX y_, work_y_, work_f_;
  double t_ = 0.0;
};

}  // namespace heavesim
