#include "kernel/algorithms/kinematics.hpp"

namespace heavesim {

void update_positions(const Model& model, Data& data, const VectorX& q) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const Link& link = model.links[i];
    std::visit(
        [&](const auto& type) {
          using J = std::decay_t<decltype(type)>;
          const double* qi = q.data() + joint.q_index;
          data.X_parent_link[i] = joint.placement * type.transform(qi);
          data.X_world_link[i] = data.X_world_link[joint.parent] * data.X_parent_link[i];
          if constexpr (J::nv > 0) {
            const MotionSubspace<J::nv> S_local = type.motion_subspace(qi);
            for (int k = 0; k < J::nv; ++k)
              data.motion_subspace_world.col(joint.v_index + k) =
                  data.X_world_link[i].act(Motion(Vector6(S_local.col(k)))).vector();
          }
        },
        joint.type);

    const Inertia inertia_world = link.inertia.transformed(data.X_world_link[i]);
    data.inertia_world[i] = inertia_world.matrix();
    if (link.added_inertia)
      data.inertia_world[i] += transform_spatial_inertia(data.X_world_link[i], *link.added_inertia);
    data.gravity_force_world[i] = Force::at_point(inertia_world.com(), inertia_world.mass() * model.gravity);
  }
}

void update_velocities(const Model& model, Data& data, const VectorX& q, const VectorX& v) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const Motion& v_parent = data.velocity_world[joint.parent];
    Motion joint_velocity;
    if (joint.nv > 0)
      joint_velocity = Motion(Vector6(data.motion_subspace_world.middleCols(joint.v_index, joint.nv) *
                                      v.segment(joint.v_index, joint.nv)));
    data.velocity_world[i] = v_parent + joint_velocity;
    // Since v_i = v_parent + v_J, v_i x v_J = v_parent x v_J (Featherstone eq. 7.7 in world form).
    Motion bias = v_parent.cross(joint_velocity);
    std::visit(
        [&](const auto& type) {
          using J = std::decay_t<decltype(type)>;
          if constexpr (J::has_bias_acceleration)
            bias += data.X_world_link[i].act(
                type.bias_acceleration(q.data() + joint.q_index, v.data() + joint.v_index));
        },
        joint.type);
    data.bias_acceleration_world[i] = bias;
    data.bias_force_world[i] = data.velocity_world[i].cross(data.inertia_world[i] * data.velocity_world[i]);
  }
}

}  // namespace heavesim
