#pragma once
// A MultibodySystem as an OdeSystem, for the explicit methods (RK4, ARKODE ERK):
// y = [q; v; z], dy/dt from MultibodySystem::state_derivative; after each step
// project() renormalizes quaternions and moves (q, v) back onto Phi = 0, J v = nu.
#include "kernel/system/multibody_system.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim {

class OdeForm final : public OdeSystem {
 public:
  explicit OdeForm(MultibodySystem& system);

  int size() const override { return system_.size(); }
  void derivative(double t, const VectorX& y, VectorX& ydot) override { system_.state_derivative(t, y, ydot); }
  void project(double t, VectorX& y) override;

 private:
  MultibodySystem& system_;
  VectorX q_, v_;  // the projected configuration and speeds
};

}  // namespace heavesim
