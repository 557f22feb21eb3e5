#pragma once
// Joint reaction wrenches: what each joint transmits from parent to child.
#include "kernel/algorithms/inverse_dynamics.hpp"

namespace heavesim {

/// The wrench exerted BY the parent ON the child through a joint, reduced to the
/// joint frame origin (the child-side joint frame = link frame). It is the total
/// transmitted wrench (SD/FAST and Simbody convention): along the joint's free
/// directions it equals the joint's own spring/actuator force (zero for a passive
/// joint); across them it is the constraint reaction.
struct JointReaction {
  Vector3 force_world;   // N, world axes
  Vector3 moment_world;  // N m, world axes, about the joint origin
  Vector3 force_joint;   // N, the user's child-side joint frame axes
  Vector3 moment_joint;  // N m, the same axes, about the joint origin
};

/// Fills data.joint_wrench_world for the accelerations in data.qdd (call after
/// forward dynamics with the same external forces): an inverse-dynamics pass. A tree
/// whose accelerations ABA gave needs none (articulated_body_joint_wrenches); loops,
/// forward dynamics by CRBA and a prescribed motion take this pass, only when reactions
/// are asked for.
void compute_joint_wrenches(const Model& model, Data& data, ExternalForces external_forces_world = {});

/// Reaction of joint i (>= 1) from data.joint_wrench_world.
JointReaction joint_reaction(const Model& model, const Data& data, int joint_index);

}  // namespace heavesim
