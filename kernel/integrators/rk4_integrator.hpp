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

 private:
  void take_step(double h);

  double step_;
  OdeSystem& system_;
  double t_ = 0.0;
  VectorX y_, k1_, k2_, k3_, k4_, stage_;
  IntegratorStatistics statistics_;
};

}  // namespace heavesim
