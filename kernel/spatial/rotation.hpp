#pragma once
// Rotation helpers: unit quaternions stored as (w, x, y, z) in state vectors.
#include <cmath>

#include "kernel/spatial/types.hpp"

namespace heavesim {

/// Rotation about a unit axis by an angle [rad]: Rodrigues' formula
/// R = c 1 + s [a]x + (1 - c) a a^T.
HEAVESIM_INLINE Matrix3 axis_angle_rotation(const Vector3& unit_axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = unit_axis.x(), y = unit_axis.y(), z = unit_axis.z();
  Matrix3 R;
  R << t * x * x + c, t * x * y - s * z, t * x * z + s * y,  //
      t * x * y + s * z, t * y * y + c, t * y * z - s * x,   //
      t * x * z - s * y, t * y * z + s * x, t * z * z + c;
  return R;
}

/// Quaternion from 4 consecutive state entries (w, x, y, z), normalized.
inline Eigen::Quaterniond quaternion_from_wxyz(const Eigen::Ref<const Eigen::Vector4d>& wxyz) {
  Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  q.normalize();
  return q;
}

inline void write_wxyz(const Eigen::Quaterniond& q, Eigen::Ref<Eigen::Vector4d> out) {
  out[0] = q.w();
  out[1] = q.x();
  out[2] = q.y();
  out[3] = q.z();
}

/// Time derivative of a (w, x, y, z) quaternion for angular velocity omega given in
/// the rotated (body) frame: dq/dt = 1/2 q (x) (0, omega).
/// The term k (1 - |q|^2) q makes the unit sphere attracting for integrators that
/// cannot project (IDA), without changing the motion on the sphere
/// (quaternion feedback normalisation; the kernel only ever uses q/|q|).
inline void quaternion_derivative(const Eigen::Ref<const Eigen::Vector4d>& wxyz,
                                  const Vector3& omega_body, Eigen::Ref<Eigen::Vector4d> out,
                                  double normalization_rate = 1.0) {
  const double w = wxyz[0], x = wxyz[1], y = wxyz[2], z = wxyz[3];
  const double ox = omega_body.x(), oy = omega_body.y(), oz = omega_body.z();
  const double correction = normalization_rate * (1.0 - (w * w + x * x + y * y + z * z));
  out[0] = 0.5 * (-x * ox - y * oy - z * oz) + correction * w;
  out[1] = 0.5 * (w * ox + y * oz - z * oy) + correction * x;
  out[2] = 0.5 * (w * oy - x * oz + z * ox) + correction * y;
  out[3] = 0.5 * (w * oz + x * oy - y * ox) + correction * z;
}

/// Rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion.
inline Vector3 rotation_vector(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in;
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec();
  return 2.0 * std::atan2(s, q.w()) * q.vec() / s;
}

}  // namespace heavesim
