#pragma once
// Fixed-size Eigen aliases shared by the whole kernel.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

/// For the few tiny spatial operations that sit in every per-body loop: GCC does not
/// always inline them into the large algorithm bodies, and the call costs more than
/// the arithmetic.
#define HEAVESIM_INLINE [[gnu::always_inline]] inline

namespace heavesim {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using VectorX = Eigen::VectorXd;
using MatrixX = Eigen::MatrixXd;
/// 6 x n matrix of spatial motion columns (e.g. motion subspaces, Jacobians).
using Matrix6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;

/// std::vector with the allocator Eigen's fixed-size vectorizable types need.
template <class T>
using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

/// Skew-symmetric cross-product matrix: skew(a) * b == a.cross(b).
inline Matrix3 skew(const Vector3& a) {
  Matrix3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace heavesim
