#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Rotation by angle q [rad] about the joint frame's z axis; v = dq/dt [rad/s].
/// S = [e_z; 0], c_J = 0; in the world S = [R e_z; p x R e_z] (third column of R).
struct RevoluteJoint : PlainCoordinates<1> {
  static constexpr const char* type_name = "revolute";
  static constexpr bool has_bias_acceleration = false;

  Transform transform(const double* q) const {
    return Transform::from_rotation(axis_angle_rotation(Vector3::UnitZ(), q[0]));
  }
  MotionSubspace<1> motion_subspace(const double*) const {
    MotionSubspace<1> S;
    S << 0, 0, 1, 0, 0, 0;
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  HEAVESIM_INLINE void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    rotate_about_z(X_world_joint, q[0], X_world_link);
  }
  HEAVESIM_INLINE void world_motion_subspace(const Transform& X_world_link, const double*, double* S) const {
    const Vector3 axis = X_world_link.rotation().col(2);
    map3(S) = axis;
    map3(S + 3) = X_world_link.translation().cross(axis);
  }
};

}  // namespace heavesim
