#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Rotation q[0] [rad] about and translation q[1] [m] along the joint frame's z axis.
/// S = [[e_z, 0]; [0, e_z]] (z is invariant under the joint's own motion), c_J = 0.
struct CylindricalJoint : PlainCoordinates<2> {
  static constexpr const char* type_name = "cylindrical";
  static constexpr bool has_bias_acceleration = false;

  Transform transform(const double* q) const {
    return Transform(axis_angle_rotation(Vector3::UnitZ(), q[0]), Vector3(0.0, 0.0, q[1]));
  }
  MotionSubspace<2> motion_subspace(const double*) const {
    MotionSubspace<2> S = MotionSubspace<2>::Zero();
    S(2, 0) = 1.0;
    S(5, 1) = 1.0;
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  HEAVESIM_INLINE void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    rotate_about_z(X_world_joint, q[0], X_world_link);
    X_world_link.translation() += q[1] * X_world_joint.rotation().col(2);
  }
  HEAVESIM_INLINE void world_motion_subspace(const Transform& X_world_link, const double*, double* S) const {
    const Vector3 axis = X_world_link.rotation().col(2);
    map3(S) = axis;
    map3(S + 3) = X_world_link.translation().cross(axis);
    map3(S + 6) = Vector3::Zero();
    map3(S + 9) = axis;
  }
};

}  // namespace heavesim
