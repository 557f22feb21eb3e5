#pragma once
// A multibody model with its force elements, as one ODE for the integrators:
//   y = [q (nq); v (nv); z_1; ...; z_k]   (z_e: internal states of force element e)
//   dq/dt = N(q) v,  dv/dt = FD(q, v, tau, f_ext),  dz_e/dt = g_e(t, q, v, z_e).
#include <memory>
#include <vector>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/system/force_element.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim {

class MultibodySystem : public OdeSystem {
 public:
  explicit MultibodySystem(std::shared_ptr<const Model> model,
                           ForwardDynamicsMethod method = ForwardDynamicsMethod::articulated_body);

  void add_force_element(std::unique_ptr<ForceElement> element);

  int size() const override { return size_; }
  void derivative(double t, const VectorX& y, VectorX& ydot) override;
  void project(double t, VectorX& y) override;

  /// Evaluates the full pipeline at (t, y) for outputs: stages, forces, qdd and,
  /// when asked, the joint wrenches. Results stay in data().
  void evaluate(double t, const VectorX& y, bool compute_reactions);

  /// Initial state: q0, v0 and every element's initial internal state.
  VectorX initial_state(const VectorX& q0, const VectorX& v0) const;

  const Model& model() const { return *model_; }
  const Data& data() const { return data_; }
  const AppliedForces& applied_forces() const { return forces_; }
  const std::vector<std::unique_ptr<ForceElement>>& force_elements() const { return elements_; }
  /// Offset of element e's internal states in y.
  int state_offset(std::size_t element) const { return state_offsets_[element]; }
  const VectorX& configuration() const { return q_; }
  const VectorX& velocity() const { return v_; }

 private:
  /// Stages, applied forces and qdd at (t, y); leaves q_, v_ and data_ consistent.
  void compute_accelerations(double t, const VectorX& y);
  /// Names the first joint with a non-finite acceleration (for the diagnosis).
  [[noreturn]] void report_non_finite(double t) const;

  std::shared_ptr<const Model> model_;
  ForwardDynamicsMethod method_;
  Data data_;
  AppliedForces forces_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::vector<int> state_offsets_;
  int size_;
  VectorX q_, v_;
};

}  // namespace heavesim
