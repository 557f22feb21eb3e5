#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Rigid connection (0 DoF). Kept as its own link so that its reaction (e.g. the hook
/// load between top drive and drill string) can be reported.
struct FixedJoint : PlainCoordinates<0> {
  static constexpr const char* type_name = "fixed";
  static constexpr bool has_bias_acceleration = false;

  Transform transform(const double*) const { return Transform::Identity(); }
  MotionSubspace<0> motion_subspace(const double*) const { return MotionSubspace<0>(); }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  void place(const Transform& X_world_joint, const double*, Transform& X_world_link) const {
    X_world_link = X_world_joint;
  }
  void world_motion_subspace(const Transform&, const double*, double*) const {}
};

}  // namespace heavesim
