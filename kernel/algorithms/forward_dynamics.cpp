#include "kernel/algorithms/forward_dynamics.hpp"

namespace heavesim {

const VectorX& composite_rigid_body_forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                                     ExternalForces external_forces_world) {
  data.qdd.setZero();
  const VectorX& bias = inverse_dynamics(model, data, data.qdd, external_forces_world);  // C(q, v) - Q_ext
  data.qdd = tau - bias;
  factorize_mass_matrix(model, data).solveInPlace(data.qdd);
  data.stages.accelerations_computed();
  return data.qdd;
}

const VectorX& forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                ExternalForces external_forces_world, ForwardDynamicsMethod method) {
  if (method == ForwardDynamicsMethod::composite_rigid_body)
    return composite_rigid_body_forward_dynamics(model, data, tau, external_forces_world);
  return articulated_body_forward_dynamics(model, data, tau, external_forces_world);
}

}  // namespace heavesim
