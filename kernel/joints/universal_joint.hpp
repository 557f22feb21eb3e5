#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Hooke joint: rotation q[0] about the joint frame's x axis, then q[1] about the
/// intermediate frame's y axis: R = Rx(q0) Ry(q1); no translation.
/// Child-side angular velocity: w = Ry(q1)^T e_x qd0 + e_y qd1 = (c1, 0, s1) qd0 + e_y qd1, so
///   S = [[(c1, 0, s1), e_y]; [0, 0]],
///   c_J = dS/dt v = [(-s1, 0, c1) qd0 qd1; 0].
/// Both depend on q1 (not on q0), which derivatives of the dynamics must know.
struct UniversalJoint : PlainCoordinates<2> {
  static constexpr const char* type_name = "universal";
  static constexpr bool has_bias_acceleration = true;
  static constexpr bool has_constant_subspace = false;

  Transform transform(const double* q) const {
    return Transform::from_rotation(axis_angle_rotation(Vector3::UnitX(), q[0]) *
                                    axis_angle_rotation(Vector3::UnitY(), q[1]));
  }
  MotionSubspace<2> motion_subspace(const double* q) const {
    MotionSubspace<2> S = MotionSubspace<2>::Zero();
    S(0, 0) = std::cos(q[1]);
    S(2, 0) = std::sin(q[1]);
    S(1, 1) = 1.0;
    return S;
  }
  Motion bias_acceleration(const double* q, const double* v) const {
    return Motion(Vector3(-std::sin(q[1]), 0.0, std::cos(q[1])) * (v[0] * v[1]), Vector3::Zero());
  }
  /// dS[:, column] / dq[coordinate]: only column 0 depends, on q1: (-s1, 0, c1).
  Motion subspace_derivative(const double* q, int column, int coordinate) const {
    if (column != 0 || coordinate != 1) return Motion::Zero();
    return Motion(Vector3(-std::sin(q[1]), 0.0, std::cos(q[1])), Vector3::Zero());
  }
  /// dc_J / dq[coordinate] = (-c1, 0, -s1) qd0 qd1 for q1, zero for q0.
  Motion bias_position_derivative(const double* q, const double* v, int coordinate) const {
    if (coordinate != 1) return Motion::Zero();
    return Motion(Vector3(-std::cos(q[1]), 0.0, -std::sin(q[1])) * (v[0] * v[1]), Vector3::Zero());
  }
  /// dc_J / dv[coordinate] = (-s1, 0, c1) times the other speed.
  Motion bias_velocity_derivative(const double* q, const double* v, int coordinate) const {
    return Motion(Vector3(-std::sin(q[1]), 0.0, std::cos(q[1])) * v[1 - coordinate], Vector3::Zero());
  }
  void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    X_world_link = X_world_joint * transform(q);
  }
  void world_motion_subspace(const Transform& X_world_link, const double* q, double* S) const {
    act_on_subspace<2>(X_world_link, motion_subspace(q), S);
  }
};

}  // namespace heavesim
