#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Rotation q[0] [rad] about and translation q[1] [m] along the same unit axis.
/// S = [[axis, 0]; [0, axis]] (the axis is invariant under the joint's own motion), c_J = 0.
struct CylindricalJoint {
  static constexpr int nq = 2, nv = 2;
  static constexpr const char* type_name = "cylindrical";
  static constexpr bool has_bias_acceleration = false;
  Vector3 axis = Vector3::UnitZ();

  Transform transform(const double* q) const {
    return Transform(axis_angle_rotation(axis, q[0]), axis * q[1]);
  }
  MotionSubspace<2> motion_subspace(const double*) const {
    MotionSubspace<2> S = MotionSubspace<2>::Zero();
    S.col(0).head<3>() = axis;
    S.col(1).tail<3>() = axis;
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
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
