#pragma once
#include <cstdio>  // arkode_butcher.h uses FILE without including it

#include <arkode/arkode_butcher_erk.h>
#include <nvector/nvector_serial.h>

#include "kernel/integrators/explicit_stability.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/integrators/sundials_support.hpp"

namespace heavesim {

/// Adaptive explicit Runge-Kutta from SUNDIALS ARKODE (ERKStep) with an embedded
/// error estimate; the state is projected (quaternions renormalized) after each step.
/// Every output time is a stop time, so the state reported there comes from a step
/// that ends on it, at the method's own order and projected: ARKODE's dense output is
/// a Hermite interpolant of degree <= 5, below the order of Verner 6(5) and Fehlberg
/// 8(7), and an interpolated state is not on the constraint manifold (measured on
/// Andrews' mechanism: both levelled off at 8-9 significant digits while interpolating).
class ErkIntegrator : public Integrator {
 public:
  ErkIntegrator(OdeSystem& system, const IntegratorSettings& settings, ARKODE_ERKTableID table);
  ~ErkIntegrator() override;
  void initialize(double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return y_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override;

 private:
  static int rhs(double t, N_Vector y, N_Vector ydot, void* user_data);
  static int project_step(double t, N_Vector y, void* user_data);
  void release();
  /// Throws the NumericalError of a failed ERKStepEvolve towards t_out.
  [[noreturn]] void fail(int flag, double t_out, double t_reached);

  IntegratorSettings settings_;
  ARKODE_ERKTableID table_;
  ButcherTableau tableau_;  // table_'s coefficients, for the stability limit of a failure
  OdeSystem& system_;
  sundials::Context context_;
  sundials::CallbackError callback_error_;
  void* arkode_ = nullptr;
  N_Vector y_nv_ = nullptr;
  VectorX y_, work_y_, work_f_;
  double t_ = 0.0;
};

}  // namespace heavesim
