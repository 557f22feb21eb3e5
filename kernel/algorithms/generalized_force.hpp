#pragma once
// The generalized force of applied loads: Q = tau + sum_i J_i^T f_i, with tau the
// generalized forces along the joint coordinates (nv; N or N m) and f_i the world
// wrench (about the world origin) on link i, J_i the link's world spatial-velocity
// Jacobian. Computed in O(n) by one backward pass (Featherstone 2008, sec. 5.3): the
// subtree sum F_i = f_i + sum_{children c} F_c is what joint i's coordinates see,
// Q_k = S_k^T F_i for every column S_k of joint i's world motion subspace.
#include "kernel/model/data.hpp"

namespace heavesim {

/// out (nv) = joint_force + sum_i J_i^T external_force_world[i], with the motion
/// subspaces of `stages` (its position stage must be current). subtree_forces is a
/// workspace of model.num_links() wrenches; nothing allocates once out has size nv.
void generalized_applied_force(const Model& model, const Data& stages, const AlignedVector<Force>& external_force_world,
                               const VectorX& joint_force, AlignedVector<Force>& subtree_forces, VectorX& out);

}  // namespace heavesim
