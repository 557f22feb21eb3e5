#include "kernel/algorithms/generalized_force.hpp"

namespace heavesim {

void generalized_applied_force(const Model& model, const Data& stages, const AlignedVector<Force>& external_force_world,
                               const VectorX& joint_force, AlignedVector<Force>& subtree_forces, VectorX& out) {
  // Links are in depth-first order, so walking backwards finishes every subtree sum
  // before its parent reads it.
  subtree_forces = external_force_world;
  out = joint_force;
  for (int i = model.num_links() - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    for (int c = 0; c < joint.nv; ++c)
      out[joint.v_index + c] += dot(stages.motion_subspace_world.col(joint.v_index + c), subtree_forces[i]);
    if (joint.parent > 0) subtree_forces[joint.parent] += subtree_forces[i];
  }
}

}  // namespace heavesim
