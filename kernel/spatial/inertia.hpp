#pragma once
// Rigid-body spatial inertia and general 6x6 spatial inertia operations.
#include "kernel/spatial/transform.hpp"

namespace heavesim {

/// Rigid-body inertia expressed in some frame F:
///   mass            m      [kg]
///   com             c_F    [m]      centre of mass, F coordinates
///   inertia_com     I_c    [kg m^2] rotational inertia about the CoM, F axes
/// As a 6x6 operator on [omega; v] (Featherstone eq. 2.63):
///   [ I_c + m [c]x[c]x^T   m [c]x ]
///   [ m [c]x^T             m 1    ]
class Inertia {
 public:
  Inertia() : mass_(0.0), com_(Vector3::Zero()), inertia_com_(Matrix3::Zero()) {}
  Inertia(double mass, const Vector3& com, const Matrix3& inertia_com)
      : mass_(mass), com_(com), inertia_com_(inertia_com) {}

  double mass() const { return mass_; }
  const Vector3& com() const { return com_; }
  const Matrix3& inertia_com() const { return inertia_com_; }

  /// Momentum h = I v: linear m (v - c x w), angular I_c w + c x linear.
  HEAVESIM_INLINE Force operator*(const Motion& m) const {
    const Vector3 linear = mass_ * (m.linear() - com_.cross(m.angular()));
    return Force(inertia_com_ * m.angular() + com_.cross(linear), linear);
  }

  /// As a 6x6 operator on [omega; v]. The parallel-axis sum is written out here and in
  /// InertiaAboutOrigin::assign: delegating to that class cost ABA 8-10 % (a temporary's
  /// stores reloaded as a 6x6; docs/performance.md).
  Matrix6 matrix() const {
    // -m [c]x [c]x = m (|c|^2 1 - c c^T), written out (this runs once per body per step).
    Matrix6 I;
    const double m = mass_;
    const double cx = com_.x(), cy = com_.y(), cz = com_.z();
    const double mx = m * cx, my = m * cy, mz = m * cz;
    I(0, 0) = inertia_com_(0, 0) + my * cy + mz * cz;
    I(1, 1) = inertia_com_(1, 1) + mx * cx + mz * cz;
    I(2, 2) = inertia_com_(2, 2) + mx * cx + my * cy;
    I(0, 1) = I(1, 0) = inertia_com_(0, 1) - mx * cy;
    I(0, 2) = I(2, 0) = inertia_com_(0, 2) - mx * cz;
    I(1, 2) = I(2, 1) = inertia_com_(1, 2) - my * cz;
    // m [c]x and its transpose.
    I(0, 3) = 0.0, I(0, 4) = -mz, I(0, 5) = my;
    I(1, 3) = mz, I(1, 4) = 0.0, I(1, 5) = -mx;
    I(2, 3) = -my, I(2, 4) = mx, I(2, 5) = 0.0;
    I.bottomLeftCorner<3, 3>() = I.topRightCorner<3, 3>().transpose();
    I.bottomRightCorner<3, 3>() = m * Matrix3::Identity();
    return I;
  }

  /// This inertia given in frame B, re-expressed in frame A (X = X_A_B).
  HEAVESIM_INLINE Inertia transformed(const Transform& X_A_B) const {
    const Matrix3& R = X_A_B.rotation();
    return Inertia(mass_, X_A_B.act_point(com_), R * inertia_com_ * R.transpose());
  }

  /// Combined inertia of two bodies expressed in the same frame.
  Inertia operator+(const Inertia& other) const {
    const double m = mass_ + other.mass_;
    if (m <= 0.0) return Inertia();
    const Vector3 c = (mass_ * com_ + other.mass_ * other.com_) / m;
    const Vector3 d1 = com_ - c, d2 = other.com_ - c;
    const Matrix3 shift1 = mass_ * (d1.squaredNorm() * Matrix3::Identity() - d1 * d1.transpose());
    const Matrix3 shift2 = other.mass_ * (d2.squaredNorm() * Matrix3::Identity() - d2 * d2.transpose());
    return Inertia(m, c, inertia_com_ + shift1 + other.inertia_com_ + shift2);
  }

  /// Kinetic energy 1/2 v^T I v [J] of a body moving with spatial velocity v.
  double kinetic_energy(const Motion& v) const { return 0.5 * dot(v, (*this) * v); }

 private:
  double mass_;
  Vector3 com_;
  Matrix3 inertia_com_;
};

/// The rigid-body inertia of one or more bodies about the origin of the frame it is
/// expressed in, in the parameters that simply add when bodies are lumped together
/// (Featherstone 2008, sec. 2.13 and 2.15):
///   mass            m    [kg]
///   first_moment    h    [kg m]   = m c
///   about_origin    I_O  [kg m^2] = I_c + m (|c|^2 1 - c c^T), frame axes
/// As a 6x6 operator on [omega; v]: [I_O  [h]x ; [h]x^T  m 1]. The composite inertias of
/// CRBA add 13 numbers per body this way instead of 36, and apply in 27 multiplications.
class InertiaAboutOrigin {
 public:
  InertiaAboutOrigin() : mass_(0.0), first_moment_(Vector3::Zero()), about_origin_(Matrix3::Zero()) {}
  /// A body's inertia (about its CoM, this frame's axes) moved to the frame's origin by
  /// the parallel-axis term -m [c]x [c]x = m (|c|^2 1 - c c^T).
  explicit InertiaAboutOrigin(const Inertia& inertia) { assign(inertia); }
  /// The same, in place (CRBA writes each composite where it is kept: a temporary's
  /// scalar stores reloaded as 16-byte copies would stall store forwarding).
  HEAVESIM_INLINE void assign(const Inertia& inertia) {
    // m (|c|^2 1 - c c^T) written out, each entry stored once and not read back: an
    // Eigen read-modify-write of the diagonal reloaded 16 bytes across two stores, a
    // store-forwarding stall that was 14 % of CRBA.
    const double m = inertia.mass(), cx = inertia.com().x(), cy = inertia.com().y(), cz = inertia.com().z();
    const double hx = m * cx, hy = m * cy, hz = m * cz;
    const Matrix3& I = inertia.inertia_com();
    mass_ = m;
    first_moment_ = Vector3(hx, hy, hz);
    about_origin_(0, 0) = I(0, 0) + hy * cy + hz * cz;
    about_origin_(1, 1) = I(1, 1) + hx * cx + hz * cz;
    about_origin_(2, 2) = I(2, 2) + hx * cx + hy * cy;
    about_origin_(0, 1) = about_origin_(1, 0) = I(0, 1) - hx * cy;
    about_origin_(0, 2) = about_origin_(2, 0) = I(0, 2) - hx * cz;
    about_origin_(1, 2) = about_origin_(2, 1) = I(1, 2) - hy * cz;
  }

  double mass() const { return mass_; }
  const Vector3& first_moment() const { return first_moment_; }
  const Matrix3& about_origin() const { return about_origin_; }
  /// As a 6x6 operator on [omega; v].
  Matrix6 matrix() const {
    Matrix6 I;
    I.topLeftCorner<3, 3>() = about_origin_;
    I.topRightCorner<3, 3>() = skew(first_moment_);
    I.bottomLeftCorner<3, 3>() = -skew(first_moment_);
    I.bottomRightCorner<3, 3>() = mass_ * Matrix3::Identity();
    return I;
  }

  HEAVESIM_INLINE InertiaAboutOrigin& operator+=(const InertiaAboutOrigin& other) {
    mass_ += other.mass_;
    first_moment_ += other.first_moment_;
    about_origin_ += other.about_origin_;
    return *this;
  }

  /// Momentum h = I v: angular I_O w + h x v, linear m v - h x w.
  HEAVESIM_INLINE Force operator*(const Motion& v) const {
    return Force(about_origin_ * v.angular() + first_moment_.cross(v.linear()),
                 mass_ * v.linear() - first_moment_.cross(v.angular()));
  }

 private:
  double mass_;
  Vector3 first_moment_;
  Matrix3 about_origin_;
};

/// A general symmetric 6x6 spatial inertia (articulated, composite, or including
/// hydrodynamic added mass) given in frame B, re-expressed in frame A:
///   I_A = X_A_B^* I_B X_A_B^{-1}.
/// With blocks [A B; B^T C] rotated into A axes and then shifted by P = [p]x:
///   C_A = C', B_A = B' + P C', A_A = A' - B'P + P B'^T - P C' P.
inline Matrix6 transform_spatial_inertia(const Transform& X_A_B, const Matrix6& I_B) {
  const Matrix3& R = X_A_B.rotation();
  const Matrix3 P = skew(X_A_B.translation());
  const Matrix3 A = R * I_B.topLeftCorner<3, 3>() * R.transpose();
  const Matrix3 B = R * I_B.topRightCorner<3, 3>() * R.transpose();
  const Matrix3 C = R * I_B.bottomRightCorner<3, 3>() * R.transpose();
  const Matrix3 PC = P * C;
  Matrix6 I_A;
  I_A.bottomRightCorner<3, 3>() = C;
  I_A.topRightCorner<3, 3>() = B + PC;
  I_A.bottomLeftCorner<3, 3>() = (B + PC).transpose();
  I_A.topLeftCorner<3, 3>() = A - B * P + P * B.transpose() - PC * P;
  return I_A;
}

/// I v for a general 6x6 spatial inertia, block by block.
HEAVESIM_INLINE Force operator*(const Matrix6& I, const Motion& v) {
  return Force(I.topLeftCorner<3, 3>() * v.angular() + I.topRightCorner<3, 3>() * v.linear(),
               I.bottomLeftCorner<3, 3>() * v.angular() + I.bottomRightCorner<3, 3>() * v.linear());
}

}  // namespace heavesim
