#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// Ball joint. q = unit quaternion (w, x, y, z) of the child-side frame in the
/// parent-side frame; v = angular velocity [rad/s] in child-side coordinates.
/// S = [1; 0], c_J = 0 (Pinocchio's local convention).
struct SphericalJoint {
  static constexpr int nq = 4, nv = 3;
  static constexpr const char* type_name = "spherical";
  static constexpr bool has_bias_acceleration = false;
  static constexpr bool has_constant_subspace = true;

  Transform transform(const double* q) const {
    return Transform::from_rotation(quaternion_from_wxyz(map4(q)).toRotationMatrix());
  }
  MotionSubspace<3> motion_subspace(const double*) const {
    MotionSubspace<3> S;
    S << Matrix3::Identity(), Matrix3::Zero();
    return S;
  }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    X_world_link = X_world_joint * transform(q);
  }
  void world_motion_subspace(const Transform& X_world_link, const double* q, double* S) const {
    act_on_subspace<nv>(X_world_link, motion_subspace(q), S);
  }
  void configuration_derivative(const double* q, const double* v, double* qdot) const {
    quaternion_derivative(map4(q), map3(v), map4(qdot));
  }
  void integrate(const double* q, const double* v, double dt, double* q_out) const {
    integrate_quaternion(q, map3(v), dt, q_out);
  }
  void difference(const double* q0, const double* q1, double* dv) const { map3(dv) = quaternion_difference(q0, q1); }
  void neutral(double* q) const {
    q[0] = 1.0;
    q[1] = q[2] = q[3] = 0.0;
  }
  void normalize(double* q) const { map4(q).normalize(); }
};

}  // namespace heavesim
