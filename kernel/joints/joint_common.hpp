#pragma once
// What every joint type provides (checked at compile time by the variant visitors).
// Joint types are canonical: the model builder rotates each joint's frames once so
// that a revolute, prismatic or cylindrical axis is the joint frame's z axis and a
// universal joint turns about x then y (Model::Joint keeps the rotation back to the
// user's axes). That makes X_J sparse, which is most of the kernel's per-body cost.
//
//   static constexpr int nq, nv;          configuration and velocity sizes
//   static constexpr const char* type_name;
//   static constexpr bool has_bias_acceleration;
//   Transform transform(const double* q)  X_J: the child-side frame in the parent-side frame
//   MotionSubspace motion_subspace(q)     S (6 x nv): the child side's relative spatial
//                                         velocity is S v, in child-side coordinates
//   Motion bias_acceleration(q, v)        c_J = (dS/dt) v, child-side coordinates
//                                         (Featherstone 2008, eq. 4.13); only read when
//                                         has_bias_acceleration
//   void place(X_world_joint, q, X_world_link)      X_world_link = X_world_joint X_J(q),
//                                         exploiting the sparsity of X_J
//   void world_motion_subspace(X_world_link, q, S)  S_world = X_world_link S (6 x nv,
//                                         column-major at S)
//   static constexpr bool has_constant_subspace     S and c_J do not depend on the
//                                         joint's own q; otherwise the joint provides
//                                         (local coordinates, for derivatives of dynamics):
//     Motion subspace_derivative(q, column, coordinate)  dS[:, column] / dq[coordinate]
//     Motion bias_position_derivative(q, v, coordinate)  dc_J / dq[coordinate]
//     Motion bias_velocity_derivative(q, v, coordinate)  dc_J / dv[coordinate]
//   void configuration_derivative(q, v, qdot)     qdot = N(q) v
//   void integrate(q, v, dt, q_out)       q_out = q "+" v dt, staying on the manifold
//   void difference(q0, q1, dv)           dv such that integrate(q0, dv, 1) = q1
//   void neutral(q), normalize(q)
//
// Raw pointers index into the model-wide q and v vectors; each joint reads nq / nv
// entries from them.
#include "kernel/spatial/rotation.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim {

template <int NV>
using MotionSubspace = Eigen::Matrix<double, 6, NV>;

/// Views of joint entries inside the model-wide q / v vectors.
inline Eigen::Map<Vector3> map3(double* p) { return Eigen::Map<Vector3>(p); }
inline Eigen::Map<const Vector3> map3(const double* p) { return Eigen::Map<const Vector3>(p); }
inline Eigen::Map<Eigen::Vector4d> map4(double* p) { return Eigen::Map<Eigen::Vector4d>(p); }
inline Eigen::Map<const Eigen::Vector4d> map4(const double* p) { return Eigen::Map<const Eigen::Vector4d>(p); }

/// The configuration maps of a joint whose N coordinates are plain numbers (angles,
/// displacements): qdot = v, integrate is q + v dt.
template <int N>
struct PlainCoordinates {
  static constexpr int nq = N, nv = N;
  static constexpr bool has_constant_subspace = true;
  void configuration_derivative(const double*, const double* v, double* qdot) const {
    for (int k = 0; k < N; ++k) qdot[k] = v[k];
  }
  void integrate(const double* q, const double* v, double dt, double* q_out) const {
    for (int k = 0; k < N; ++k) q_out[k] = q[k] + v[k] * dt;
  }
  void difference(const double* q0, const double* q1, double* dv) const {
    for (int k = 0; k < N; ++k) dv[k] = q1[k] - q0[k];
  }
  void neutral(double* q) const {
    for (int k = 0; k < N; ++k) q[k] = 0.0;
  }
  void normalize(double*) const {}
};

/// q_out = q (x) exp(omega dt / 2) for unit quaternions (w, x, y, z): exact for a
/// constant angular velocity omega [rad/s] given in the rotated (body) frame.
inline void integrate_quaternion(const double* q, const Vector3& omega, double dt, double* q_out) {
  const Eigen::Quaterniond q0 = quaternion_from_wxyz(map4(q));
  const Vector3 rotation = omega * dt;
  const double angle = rotation.norm();
  const Eigen::Quaterniond dq = angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle))
                                            : Eigen::Quaterniond::Identity();
  write_wxyz((q0 * dq).normalized(), map4(q_out));
}

/// The rotation vector taking unit quaternion q0 to q1, in q0's frame.
inline Vector3 quaternion_difference(const double* q0, const double* q1) {
  return rotation_vector(quaternion_from_wxyz(map4(q0)).conjugate() * quaternion_from_wxyz(map4(q1)));
}

/// X_out = X * Rz(angle) for c = cos(angle), s = sin(angle), computed on the two columns
/// Rz changes.
HEAVESIM_INLINE void rotate_about_z(const Transform& X, double c, double s, Transform& X_out) {
  const Matrix3& R = X.rotation();
  Matrix3& R_out = X_out.rotation();
  const Vector3 x = R.col(0), y = R.col(1);
  R_out.col(0) = c * x + s * y;
  R_out.col(1) = c * y - s * x;
  R_out.col(2) = R.col(2);
  X_out.translation() = X.translation();
}

/// X_out = X * Rz(angle).
HEAVESIM_INLINE void rotate_about_z(const Transform& X, double angle, Transform& X_out) {
  rotate_about_z(X, std::cos(angle), std::sin(angle), X_out);
}

/// S_world = X S for a general joint (column by column).
template <int NV>
HEAVESIM_INLINE void act_on_subspace(const Transform& X, const MotionSubspace<NV>& S_local, double* S_world) {
  for (int k = 0; k < NV; ++k) {
    const Motion column = X.act(Motion(S_local.col(k)));
    map3(S_world + 6 * k) = column.angular();
    map3(S_world + 6 * k + 3) = column.linear();
  }
}

}  // namespace heavesim
