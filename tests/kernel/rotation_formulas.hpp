#pragma once
// Elementary rotations written out for the kernel tests, independently of
// kernel/spatial/rotation.hpp, so that joint transforms and kinematics are compared
// with textbook formulas rather than with the code under test.
#include <Eigen/Dense>

#include <cmath>

namespace heavesim::test_formulas {

/// Active rotation by `angle` [rad] about the x, y or z axis (right-hand rule).
inline Eigen::Matrix3d rotation_x(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << 1, 0, 0, 0, c, -s, 0, s, c;
  return R;
}
inline Eigen::Matrix3d rotation_y(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, 0, s, 0, 1, 0, -s, 0, c;
  return R;
}
inline Eigen::Matrix3d rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

/// [a]x, the cross-product matrix: [a]x b = a x b.
inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d K;
  K << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return K;
}

/// Rodrigues' formula: rotation by |phi| about phi / |phi|,
/// R = 1 + sin(t) K + (1 - cos(t)) K^2 with K = [phi / t]x, t = |phi| > 0.
inline Eigen::Matrix3d rodrigues(const Eigen::Vector3d& phi) {
  const double t = phi.norm();
  const Eigen::Matrix3d K = cross_matrix(phi / t);
  return Eigen::Matrix3d::Identity() + std::sin(t) * K + (1.0 - std::cos(t)) * K * K;
}

/// The axial vector of a skew-symmetric matrix W = [w]x.
inline Eigen::Vector3d vee(const Eigen::Matrix3d& W) { return Eigen::Vector3d(W(2, 1), W(0, 2), W(1, 0)); }

}  // namespace heavesim::test_formulas
