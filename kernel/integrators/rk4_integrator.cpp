#include "kernel/integrators/rk4_integrator.hpp"

#include <cmath>

#include "kernel/integrators/explicit_stability.hpp"

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
  t_start_ = t_output_ = t0;
  y_start_ = y_output_ = y0;
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
  // An overflow in this last combination would otherwise reach the output unnoticed.
  if (!y_.allFinite()) {
    const StateDiagnosis note = system_.state_note(t_, y_);
    throw NumericalError(t_, note.empty() ? std::string("the state is not finite") : note.what,
                         "check the force elements acting there and the step");
  }
  system_.project(t_, y_);
  statistics_.steps += 1;
  statistics_.rhs_evaluations += 4;
  statistics_.last_step = h;
}

void Rk4Integrator::advance_to(double t_out) {
  // Steps of size h; a remainder below 1e-9 h is absorbed so outputs on the step grid
  // do not produce a spurious tiny step.
  try {
    while (t_out - t_ > 1e-9 * step_) {
      const double remaining = t_out - t_;
      take_step(remaining < step_ * (1.0 + 1e-9) ? remaining : step_);
    }
  } catch (const NumericalError& error) {
    throw explain(error);
  }
  t_ = t_out;
  t_output_ = t_;
  y_output_ = y_;
}

NumericalError Rk4Integrator::explain(const NumericalError& error) const {
  // A step beyond the stability limit makes the state grow by |R(h lambda)| per step
  // until something gives way -- an element's range (a gas volume, coincident end
  // points), a non-finite acceleration -- and that symptom names the wrong part. The
  // states at the start and at the last output are linearized (the failing step's own
  // start may already be far off); the earliest that explains the failure is reported.
  for (int point = 0; point < 2; ++point) {
    if (point == 1 && t_output_ == t_start_) break;
    const FastestMode mode = system_.fastest_mode_note(point == 0 ? t_start_ : t_output_, point == 0 ? y_start_ : y_output_);
    if (!mode.found()) continue;
    const double limit = stability_limit(classical_rk4_tableau(), mode.eigenvalue);
    if (step_ > limit) return beyond_stability_limit(error.time(), "rk4", step_, limit, mode, error.what());
  }
  return error;  // the step is stable: the failure's own diagnosis stands
}

}  // namespace heavesim
