#pragma once
// The velocity-level contact step (kernel/contact/contact_stepper.hpp) as an integrator
// of a MultibodySystem: fixed step h (the last one before an output shortened to land on
// it), the system's applied forces (joint elements and force elements) held over the
// step, contacts, joint stops and the model's constraints solved as one complementarity
// problem per step, force elements' own states stepped by explicit Euler with the step's
// starting rates. After each step the system's contact element (if any) holds the
// step's contact loads, which the recorder writes and an evaluation at an output time
// applies. First order in h; docs/physics/contact.md.
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

class ContactSteppingIntegrator : public Integrator {
 public:
  ContactSteppingIntegrator(MultibodySystem& system, double step);
  void initialize(double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return y_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override { return statistics_; }

 private:
  void take_step(double h);
  MultibodySystem& system_;
  double step_;
  ContactStepper stepper_;
  AppliedForces forces_;
  double t_ = 0.0;
  double grid_start_ = 0.0;  // s: steps of h are counted from here
  long grid_steps_ = 0;
  VectorX y_, q_, v_, zdot_;
  IntegratorStatistics statistics_;
};

}  // namespace heavesim
