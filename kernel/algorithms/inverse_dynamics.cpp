#include "kernel/algorithms/inverse_dynamics.hpp"

namespace heavesim {

const VectorX& inverse_dynamics(const Model& model, Data& data, const VectorX& qdd,
                                ExternalForces external_forces_world) {
  const int n = model.num_links();
  for (int i = 1; i < n; ++i) {
    const Joint& joint = model.joints[i];
    const Motion a = data.acceleration_world[joint.parent] + data.bias_acceleration_world[i] + joint_motion(data, joint, qdd);
    data.acceleration_world[i] = a;
    Force f = link_momentum(model, data, i, a) + data.bias_force_world[i] - link_weight(model, data, i);
    if (!external_forces_world.empty()) f -= external_forces_world[i];
    data.joint_wrench_world[i] = f;
  }
  for (int i = n - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    for (int k = 0; k < joint.nv; ++k)
      data.tau[joint.v_index + k] = dot(data.motion_subspace_world.col(joint.v_index + k), data.joint_wrench_world[i]);
    if (joint.parent > 0) data.joint_wrench_world[joint.parent] += data.joint_wrench_world[i];
  }
  data.stages.accelerations_overwritten();  // acceleration_world and the wrenches are those of `qdd`
  data.articulated_evaluation = 0;          // no longer the articulated-body pass's
  return data.tau;
}

const VectorX& rnea(const Model& model, Data& data, const VectorX& q, const VectorX& v, const VectorX& qdd,
                    ExternalForces external_forces_world) {
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  return inverse_dynamics(model, data, qdd, external_forces_world);
}

}  // namespace heavesim
