#include "kernel/integrators/rk4_integrator.hpp"

#include <cmath>

namespace heavesim {

void Rk4Integrator::initialize(double t0, const VectorX& y0) {
  t_ = t0;
  y_ = y0;
  const int n = system_.size();
  k1_.resize(n);
  k2_.resize(n);
  k3_.resize(n);
  k4_.resize(n);
  stage_.resize(n);
  statistics_ = {};
}

void Rk4Integrator::take_step(double h) {
  system_.derivative(t_, y_, k1_);
  stage_ = y_ + 0.5 * h * k1_;
  system_.derivative(t_ + 0.5 * h, stage_, k2_);
  stage_ = y_ + 0.5 * h * k2_;
  system_.derivative(t_ + 0.5 * h, stage_, k3_);
  stage_ = y_ + h * k3_;
  system_.derivative(t_ + h, stage_, k4_);
  y_ += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
  t_ += h;
  system_.project(t_, y_);
  statistics_.steps += 1;
  statistics_.rhs_evaluations += 4;
  statistics_.last_step = h;
}

void Rk4Integrator::advance_to(double t_out) {
  // Steps of size h; a remainder below 1e-9 h is absorbed so outputs on the step grid
  // do not produce a spurious tiny step.
  while (t_out - t_ > 1e-9 * step_) {
    const double remaining = t_out - t_;
    take_step(remaining < step_ * (1.0 + 1e-9) ? remaining : step_);
  }
  t_ = t_out;
}

}  // namespace heavesim
