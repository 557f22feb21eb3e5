#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Hooke joint: rotation q[0] about axis1 (parent-side joint frame), then q[1] about
/// axis2 (in the intermediate frame; equals axis2 of the joint frame at q = 0).
/// R = Rot(axis1, q0) Rot(axis2, q1); no translation.
/// Child-side angular velocity: w = R2^T axis1 qd0 + axis2 qd1, so
///   S = [[R2^T axis1, axis2]; [0, 0]],
///   c_J = dS/dt v = [-qd0 qd1 axis2 x (R2^T axis1); 0]   (dR2^T/dt = -qd1 [axis2]x R2^T).
struct UniversalJoint {
  static constexpr int nq = 2, nv = 2;
  static constexpr const char* type_name = "universal";
  static constexpr bool has_bias_acceleration = true;
  Vector3 axis1 = Vector3::UnitX();
  Vector3 axis2 = Vector3::UnitY();

  Transform transform(const double* q) const {
    return Transform::from_rotation(axis_angle_rotation(axis1, q[0]) *
                                    axis_angle_rotation(axis2, q[1]));
  }
  MotionSubspace<2> motion_subspace(const double* q) const {
    MotionSubspace<2> S = MotionSubspace<2>::Zero();
    S.col(0).head<3>() = axis_angle_rotation(axis2, q[1]).transpose() * axis1;
    S.col(1).head<3>() = axis2;
    return S;
  }
  Motion bias_acceleration(const double* q, const double* v) const {
    const Vector3 axis1_child = axis_angle_rotation(axis2, q[1]).transpose() * axis1;
    return Motion(-v[0] * v[1] * axis2.cross(axis1_child), Vector3::Zero());
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
