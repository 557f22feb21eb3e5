#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim {

void compute_joint_wrenches(const Model& model, Data& data, ExternalForces external_forces_world) {
  const bool accelerations_current = data.stages.current & StageMarker::accelerations;
  inverse_dynamics(model, data, data.qdd, external_forces_world);
  // The pass ran on data.qdd: its accelerations and wrenches belong to this evaluation
  // exactly when qdd did.
  if (accelerations_current) {
    data.stages.accelerations_computed();
    data.stages.reactions_computed();
  }
}

JointReaction joint_reaction(const Model& model, const Data& data, int joint_index) {
  const Transform& X_world_joint = data.X_world_link[joint_index];
  const Force& f = data.joint_wrench_world[joint_index];
  JointReaction reaction;
  reaction.force_world = f.linear();
  reaction.moment_world = f.moment_about(X_world_joint.translation());
  // World -> link (canonical joint) axes -> the user's joint axes.
  const Matrix3 R_joint_world = model.joints[joint_index].R_joint_link * X_world_joint.rotation().transpose();
  reaction.force_joint = R_joint_world * reaction.force_world;
  reaction.moment_joint = R_joint_world * reaction.moment_world;
  return reaction;
}

}  // namespace heavesim
