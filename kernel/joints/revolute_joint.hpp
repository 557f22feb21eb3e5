#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Rotation by angle q [rad] about a fixed unit axis (joint-frame coordinates);
/// v = dq/dt [rad/s]. S = [axis; 0], c_J = 0.
struct RevoluteJoint {
  static constexpr int nq = 1, nv = 1;
  static constexpr const char* type_name = "revolute";
  static constexpr bool has_bias_acceleration = false;
  Vector3 axis = Vector3::UnitZ();

  Transform transform(const double* q) const {
    return Transform::from_rotation(axis_angle_rotation(axis, q[0]));
  }
  MotionSubspace<1> motion_subspace(const double*) const {
    MotionSubspace<1> S;
    S << axis, Vector3::Zero();
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  void configuration_derivative(const double*, const double* v, double* qdot) const { qdot[0] = v[0]; }
  void integrate(const double* q, const double* v, double dt, double* q_out) const {
    q_out[0] = q[0] + v[0] * dt;
  }
  void difference(const double* q0, const double* q1, double* dv) const { dv[0] = q1[0] - q0[0]; }
  void neutral(double* q) const { q[0] = 0.0; }
  void normalize(double*) const {}
};

}  // namespace heavesim
