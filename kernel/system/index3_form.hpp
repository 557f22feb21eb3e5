#pragma once
// A MultibodySystem as a SecondOrderSystem (second_order_system.hpp): the equations of
// motion with every constraint row, for the index-3 augmented-Lagrangian HHT
// integrator. Redundant rows need no special care there (the augmented Lagrangian
// never inverts J M^-1 J^T), so unlike the GGL form nothing is dropped.
#include "kernel/system/dynamics_differentiator.hpp"
#include "kernel/system/fastest_mode.hpp"
#include "kernel/system/multibody_system.hpp"
#include "kernel/system/second_order_system.hpp"

namespace heavesim {

class Index3Form final : public SecondOrderSystem {
 public:
  explicit Index3Form(MultibodySystem& system);

  int configuration_size() const override { return system_.model().nq; }
  int velocity_size() const override { return system_.model().nv; }
  int constraint_size() const override { return system_.model().num_constraint_rows; }
  int element_state_size() const override { return system_.element_state_size(); }
  void integrate_configuration(const VectorX& q, const VectorX& step, VectorX& q_out) const override;
  void initial_accelerations(double t, const VectorX& y, VectorX& a, VectorX& zdot, VectorX& lambda) override;
  const std::vector<int>& independent_constraint_rows() const override { return independent_rows_; }
  void dynamics_residual(double t, const VectorX& y, const VectorX& a, const VectorX& zdot, double penalty,
                         VectorX& lambda, Eigen::Ref<VectorX> r_v, Eigen::Ref<VectorX> r_z,
                         Eigen::Ref<VectorX> phi) override;
  void dynamics_derivatives(double t, const VectorX& y, const VectorX& a, DynamicsDerivatives& out) override;
  void constraint_terms(double t, const VectorX& y, ConstraintTerms& out) override;
  void constraint_bias_at(double t, const VectorX& y, VectorX& gamma) override;
  std::string describe_component(int index) const override {
    return system_.describe_state_component(system_.model().nq + index);  // v, then z: contiguous in y
  }
  StateDiagnosis diagnose_state(double t, const VectorX& y) override { return system_.diagnose_state(t, y); }

 private:
  MultibodySystem& system_;
  DynamicsDifferentiator differentiator_;
  VectorX initial_rate_, multiplier_force_;
  std::vector<int> independent_rows_;  // set by initial_accelerations
};

}  // namespace heavesim
