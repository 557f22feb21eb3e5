#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Hooke joint: rotation q[0] about the joint frame's x axis, then q[1] about the
/// intermediate frame's y axis: R = Rx(q0) Ry(q1); no translation.
/// Child-side angular velocity: w = Ry(q1)^T e_x qd0 + e_y qd1 = (c1, 0, s1) qd0 + e_y qd1, so
///   S = [[(c1, 0, s1), e_y]; [0, 0]],
///   c_J = dS/dt v = [(-s1, 0, c1) qd0 qd1; 0].
struct UniversalJoint {
  static constexpr int nq = 2, nv = 2;
  static constexpr const char* type_name = "universal";
  static constexpr bool has_bias_acceleration = true;

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
  void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    X_world_link = X_world_joint * transform(q);
  }
  void world_motion_subspace(const Transform& X_world_link, const double* q, double* S) const {
    act_on_subspace<2>(X_world_link, motion_subspace(q), S);
  }
  void configuration_derivative(const double*, const double* v, double* qdot) const {
    qdot[0] = v[0];
    qdot[1] = v[1];
  }
  void integrate(const double* q, const double* v, double dt, double* q_out) const {
    q_out[0] = q[0] + v[0] * dt;
    q_out[1] = q[1] + v[1] * dt;
  }
  void difference(const double* q0, const double* q1, double* dv) const {
    dv[0] = q1[0] - q0[0];
    dv[1] = q1[1] - q0[1];
  }
  void neutral(double* q) const { q[0] = q[1] = 0.0; }
  void normalize(double*) const {}
};

}  // namespace heavesim
