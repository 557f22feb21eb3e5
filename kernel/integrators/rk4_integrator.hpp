#pragma once
#include "kernel/integrators/integrator.hpp"

namespace heavesim {

/// Classical 4th-order Runge-Kutta with fixed step h; the last step before an output
/// time is shortened to land on it exactly. After every step the state is projected
/// (quaternions renormalized), which keeps the order (Hairer, Lubich, Wanner IV.4).
class Rk4Integrator : public Integrator {
 public:
  Rk4Integrator(OdeSystem& system, double step) : step_(step), system_(system) {}
  void initialize(double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return y_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override { return statistics_; }
  /// The failure explained by the step's stability limit when the step is beyond it at
  /// the start of the run or at the last output; unchanged otherwise.
  NumericalError explain(const NumericalError& error) const override;

 private:
  void take_step(double h);

  double step_;
  OdeSystem& system_;
  double t_ = 0.0;
  VectorX y_, k1_, k2_, k3_, k4_, stage_;
  double t_start_ = 0.0, t_output_ = 0.0;  // s: the run's start and the last output
  VectorX y_start_, y_output_;             // the states there, sane points to linearize at
  IntegratorStatistics statistics_;
};

}  // namespace heavesim
