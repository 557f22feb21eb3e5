#include "kernel/algorithms/kinematics.hpp"

#include <stdexcept>
#include <type_traits>

#include "kernel/math/vector_libm.hpp"

namespace heavesim {

void update_positions(const Model& model, Data& data, const VectorX& q) {
  data.stages.begin_evaluation();
  data.q = q;  // same size: a copy, no allocation
  // The revolute joints' cos and sin first, two joints at a time (libmvec): a sincos was a
  // quarter of CRBA on a double pendulum.
  vector_libm::cos_sin_at(q.data(), model.revolute_coordinates, data.revolute_cos.data(), data.revolute_sin.data());
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const Link& link = model.links[i];
    std::visit(
        [&](const auto& type) {
          using J = std::decay_t<decltype(type)>;
          const double* qi = q.data() + joint.q_index;
          const Transform X_world_joint = data.X_world_link[joint.parent] * joint.placement;
          if constexpr (std::is_same_v<J, RevoluteJoint>)
            rotate_about_z(X_world_joint, data.revolute_cos[joint.q_index], data.revolute_sin[joint.q_index],
                           data.X_world_link[i]);
          else
            type.place(X_world_joint, qi, data.X_world_link[i]);
          // The joint's nv columns of the column-major 6 x nv matrix start at 6 v_index; a
          // fixed joint (nv = 0) at the end of the tree has v_index = nv, one past the last
          // column, where it writes nothing (.col() would assert on that index).
          type.world_motion_subspace(data.X_world_link[i], qi, data.motion_subspace_world.data() + 6 * joint.v_index);
        },
        joint.type);

    data.rigid_inertia_world[i] = link.inertia.transformed(data.X_world_link[i]);
    if (link.added_inertia)
      data.added_inertia_world[i] = transform_spatial_inertia(data.X_world_link[i], *link.added_inertia);
  }
}

void update_velocities(const Model& model, Data& data, const VectorX& q, const VectorX& v) {
  // The velocity stage reads the placements and world subspaces of the position stage.
  if (!(data.stages.current & StageMarker::positions))
    throw std::logic_error("update_velocities: the position stage of this Data is not current");
  data.v = v;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const Motion& v_parent = data.velocity_world[joint.parent];
    const Motion joint_velocity = joint_motion(data, joint, v);
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
    // Kept: the kinetic energy is 1/2 v_i . h_i (kernel/algorithms/energy.cpp).
    data.momentum_world[i] = link_momentum(model, data, i, data.velocity_world[i]);
    data.bias_force_world[i] = data.velocity_world[i].cross(data.momentum_world[i]);
  }
  data.stages.velocities_computed();
}

}  // namespace heavesim
