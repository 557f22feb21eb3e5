#pragma once
#include "kernel/joints/joint_common.hpp"

namespace heavesim {

/// 6-DoF floating joint. q = (x, y, z [m] of the child-side origin in the parent-side
/// frame, unit quaternion w, x, y, z of its orientation); v = (angular velocity [rad/s],
/// velocity of the child-side origin [m/s]), both in child-side (body) coordinates,
/// the usual ship convention nu = [p q r; u v w] reordered to [angular; linear].
/// S = identity, c_J = 0; qdot: position' = R v_linear, quaternion' = 1/2 q (x) w.
struct FreeJoint {
  static constexpr int nq = 7, nv = 6;
  static constexpr const char* type_name = "free";
  static constexpr bool has_bias_acceleration = false;
  static constexpr bool has_constant_subspace = true;

  Transform transform(const double* q) const {
    return Transform(quaternion_from_wxyz(map4(q + 3)).toRotationMatrix(), map3(q));
  }
  MotionSubspace<6> motion_subspace(const double*) const { return MotionSubspace<6>::Identity(); }
  Motion bias_acceleration(const double*, const double*) const { return Motion::Zero(); }
  void place(const Transform& X_world_joint, const double* q, Transform& X_world_link) const {
    X_world_link = X_world_joint * transform(q);
  }
  void world_motion_subspace(const Transform& X_world_link, const double* q, double* S) const {
    act_on_subspace<nv>(X_world_link, motion_subspace(q), S);
  }
  void configuration_derivative(const double* q, const double* v, double* qdot) const {
    map3(qdot) = quaternion_from_wxyz(map4(q + 3)) * map3(v + 3);
    quaternion_derivative(map4(q + 3), map3(v), map4(qdot + 3));
  }
  /// The SE(3) exponential: the motion with constant body-frame velocity v for dt,
  /// p(dt) = p + R V(w dt) v_linear dt, R(dt) = R exp(w dt), with
  /// V(phi) = 1 + (1 - cos t)/t^2 [phi]x + (t - sin t)/t^3 [phi]x^2, t = |phi|.
  void integrate(const double* q, const double* v, double dt, double* q_out) const {
    const Vector3 phi = map3(v) * dt;
    map3(q_out) = map3(q) + quaternion_from_wxyz(map4(q + 3)) * (left_jacobian(phi) * (map3(v + 3) * dt));
    integrate_quaternion(q + 3, map3(v), dt, q_out + 3);
  }
  /// The SE(3) logarithm of the relative pose: inverts integrate(q0, dv, 1).
  void difference(const double* q0, const double* q1, double* dv) const {
    const Vector3 phi = quaternion_difference(q0 + 3, q1 + 3);
    map3(dv) = phi;
    map3(dv + 3) = left_jacobian(phi).inverse() *
                   (quaternion_from_wxyz(map4(q0 + 3)).conjugate() * (map3(q1) - map3(q0)));
  }
  /// V(phi), the left Jacobian of SO(3) (series below 1e-4 rad to avoid cancellation).
  static Matrix3 left_jacobian(const Vector3& phi) {
    const double t = phi.norm();
    const Matrix3 K = skew(phi);
    if (t < 1e-4) return Matrix3::Identity() + 0.5 * K + (1.0 / 6.0) * K * K;
    return Matrix3::Identity() + (1.0 - std::cos(t)) / (t * t) * K + (t - std::sin(t)) / (t * t * t) * K * K;
  }
  void neutral(double* q) const {
    q[0] = q[1] = q[2] = 0.0;
    q[3] = 1.0;
    q[4] = q[5] = q[6] = 0.0;
  }
  void normalize(double* q) const { map4(q + 3).normalize(); }
};

}  // namespace heavesim
