#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Translation by q [m] along the joint frame's z axis; v = dq/dt [m/s].
/// S = [0; e_z], c_J = 0; in the world S = [0; R e_z].
struct PrismaticJoint : PlainCoordinates<1> {
  static constexpr const char* type_name = "prismatic";
  static constexpr bool has_bias_acceleration = false;

  Transform transform(const double* q) const { return Transform::from_translation(Vector3(0.0, 0.0, q[0])); }
  MotionSubspace<1> motion_subspace(const double*) const {
    MotionSubspace<1> S;
    S << 0, 0, 0, 0, 0, 1;
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  HEAVESIM_INLINE void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    X_world_link.rotation() = X_world_joint.rotation();
    X_world_link.translation() = X_world_joint.translation() + q[0] * X_world_joint.rotation().col(2);
  }
  HEAVESIM_INLINE void world_motion_subspace(const Transform& X_world_link, const double*, double* S) const {
    map3(S) = Vector3::Zero();
    map3(S + 3) = X_world_link.rotation().col(2);
  }
};

}  // namespace heavesim
