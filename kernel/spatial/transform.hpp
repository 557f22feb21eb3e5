#pragma once
// Rigid transform (placement) X_A_B: the pose of frame B in frame A.
//
//   rotation    R_A_B : maps B axes to A axes (columns are B's axes in A),
//   translation p_A_B : origin of B, in A.
// A point with coordinates r_B in B has coordinates r_A = R_A_B r_B + p_A_B.
// act()/act_inverse() change the frame in which a spatial vector is expressed
// (Featherstone's ^A X_B and its inverse), exactly like Pinocchio's SE3.
#include "kernel/spatial/spatial_vectors.hpp"

namespace heavesim {

class Transform {
 public:
  Transform() : rotation_(Matrix3::Identity()), translation_(Vector3::Zero()) {}
  Transform(const Matrix3& rotation, const Vector3& translation)
      : rotation_(rotation), translation_(translation) {}
  static Transform Identity() { return Transform(); }
  static Transform from_translation(const Vector3& p) { return Transform(Matrix3::Identity(), p); }
  static Transform from_rotation(const Matrix3& r) { return Transform(r, Vector3::Zero()); }

  const Matrix3& rotation() const { return rotation_; }
  const Vector3& translation() const { return translation_; }
  Matrix3& rotation() { return rotation_; }
  Vector3& translation() { return translation_; }

  /// X_A_C = X_A_B * X_B_C.
  HEAVESIM_INLINE Transform operator*(const Transform& X_B_C) const {
    return Transform(rotation_ * X_B_C.rotation_, translation_ + rotation_ * X_B_C.translation_);
  }
  /// X_B_A from X_A_B.
  Transform inverse() const {
    const Matrix3 Rt = rotation_.transpose();
    return Transform(Rt, -(Rt * translation_));
  }

  /// Point coordinates: r_A = X_A_B.act_point(r_B).
  HEAVESIM_INLINE Vector3 act_point(const Vector3& r_B) const { return rotation_ * r_B + translation_; }
  Vector3 act_inverse_point(const Vector3& r_A) const {
    return rotation_.transpose() * (r_A - translation_);
  }

  /// Motion expressed in B -> expressed in A (omega_A = R w_B, v_A = R v_B + p x omega_A).
  HEAVESIM_INLINE Motion act(const Motion& m_B) const {
    const Vector3 w = rotation_ * m_B.angular();
    return Motion(w, rotation_ * m_B.linear() + translation_.cross(w));
  }
  /// Motion expressed in A -> expressed in B.
  HEAVESIM_INLINE Motion act_inverse(const Motion& m_A) const {
    const Matrix3 Rt = rotation_.transpose();
    return Motion(Rt * m_A.angular(),
                  Rt * (m_A.linear() - translation_.cross(m_A.angular())));
  }
  /// Force expressed in B -> expressed in A (f_A = R f_B, n_A = R n_B + p x f_A).
  HEAVESIM_INLINE Force act(const Force& f_B) const {
    const Vector3 f = rotation_ * f_B.linear();
    return Force(rotation_ * f_B.angular() + translation_.cross(f), f);
  }
  /// Force expressed in A -> expressed in B.
  HEAVESIM_INLINE Force act_inverse(const Force& f_A) const {
    const Matrix3 Rt = rotation_.transpose();
    return Force(Rt * (f_A.angular() - translation_.cross(f_A.linear())), Rt * f_A.linear());
  }

  /// 6x6 matrix of act() on motions (Featherstone's ^A X_B).
  Matrix6 motion_matrix() const {
    Matrix6 X;
    X.topLeftCorner<3, 3>() = rotation_;
    X.topRightCorner<3, 3>().setZero();
    X.bottomLeftCorner<3, 3>() = skew(translation_) * rotation_;
    X.bottomRightCorner<3, 3>() = rotation_;
    return X;
  }

  bool is_approx(const Transform& other, double precision = 1e-12) const {
    return rotation_.isApprox(other.rotation_, precision) &&
           (translation_ - other.translation_).norm() <= precision * (1.0 + translation_.norm());
  }

 private:
  Matrix3 rotation_;
  Vector3 translation_;
};

}  // namespace heavesim
