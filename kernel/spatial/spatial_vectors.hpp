#pragma once
// Spatial motion and force vectors in Featherstone's [angular; linear] order.
//
// A Motion holds (omega, v): angular velocity and the linear velocity of the point
// at the frame origin. A Force holds (n, f): moment about the frame origin and force.
// Both are expressed in some frame that the owner names (X_world, ..._link, ...).
// Reference: R. Featherstone, Rigid Body Dynamics Algorithms (2008), ch. 2.
//
// Storage is two 3-vectors, not one packed 6-vector: nearly all spatial arithmetic
// (transforms, cross products, rigid inertias) works on the 3-vector halves, and a
// packed 6-vector built from scalar 3-vector stores and then reloaded with 16-byte
// loads stalls on store forwarding, several times per body. vector() packs a copy
// for 6x6 matrix algebra.
#include "kernel/spatial/types.hpp"

namespace heavesim {

/// What Motion and Force share: storage, packing and the vector-space operations.
/// Motions and forces never mix in these operations; Derived keeps them apart.
template <class Derived>
class SpatialVector {
 public:
  SpatialVector() : angular_(Vector3::Zero()), linear_(Vector3::Zero()) {}
  SpatialVector(const Vector3& angular, const Vector3& linear) : angular_(angular), linear_(linear) {}
  /// From any 6-vector expression [angular; linear].
  template <class Packed>
  explicit SpatialVector(const Eigen::MatrixBase<Packed>& packed)
      : angular_(packed.template head<3>()), linear_(packed.template tail<3>()) {}
  static Derived Zero() { return Derived(); }

  Vector3& angular() { return angular_; }
  const Vector3& angular() const { return angular_; }
  Vector3& linear() { return linear_; }
  const Vector3& linear() const { return linear_; }
  /// Packed copy [angular; linear].
  Vector6 vector() const {
    Vector6 packed;
    packed << angular_, linear_;
    return packed;
  }

  HEAVESIM_INLINE Derived operator+(const Derived& o) const { return Derived(angular_ + o.angular_, linear_ + o.linear_); }
  HEAVESIM_INLINE Derived operator-(const Derived& o) const { return Derived(angular_ - o.angular_, linear_ - o.linear_); }
  Derived operator-() const { return Derived(-angular_, -linear_); }
  Derived operator*(double s) const { return Derived(angular_ * s, linear_ * s); }
  HEAVESIM_INLINE Derived& operator+=(const Derived& o) {
    angular_ += o.angular_;
    linear_ += o.linear_;
    return static_cast<Derived&>(*this);
  }
  HEAVESIM_INLINE Derived& operator-=(const Derived& o) {
    angular_ -= o.angular_;
    linear_ -= o.linear_;
    return static_cast<Derived&>(*this);
  }

 protected:
  Vector3 angular_, linear_;
};

class Force;

class Motion : public SpatialVector<Motion> {
 public:
  using SpatialVector::SpatialVector;

  /// Spatial cross product for motions, this x_m m (Featherstone eq. 2.31):
  /// [w x w_m ; w x v_m + v x w_m].
  HEAVESIM_INLINE Motion cross(const Motion& m) const {
    return Motion(angular_.cross(m.angular_), angular_.cross(m.linear_) + linear_.cross(m.angular_));
  }
  /// Spatial cross product for forces, this x_f f (Featherstone eq. 2.32):
  /// [w x n + v x f ; w x f].
  HEAVESIM_INLINE Force cross(const Force& f) const;

  /// Velocity of the point p (same frame as this motion) of the moving body.
  Vector3 point_velocity(const Vector3& p) const { return linear_ + angular_.cross(p); }
};

class Force : public SpatialVector<Force> {
 public:
  using SpatialVector::SpatialVector;

  /// A force f acting at point p (both in this frame) as a spatial force about the origin.
  static Force at_point(const Vector3& p, const Vector3& f) { return Force(p.cross(f), f); }

  /// Moment of this force system about the point p (same frame).
  Vector3 moment_about(const Vector3& p) const { return angular_ - p.cross(linear_); }
};

HEAVESIM_INLINE Force Motion::cross(const Force& f) const {
  return Force(angular_.cross(f.angular()) + linear_.cross(f.linear()), angular_.cross(f.linear()));
}

/// Power of a force on a motion (both in the same frame).
HEAVESIM_INLINE double dot(const Motion& m, const Force& f) {
  return m.angular().dot(f.angular()) + m.linear().dot(f.linear());
}
/// Power of a force on a motion given as a packed 6-vector (e.g. a column of S).
template <class Derived>
HEAVESIM_INLINE double dot(const Eigen::MatrixBase<Derived>& packed_motion, const Force& f) {
  return packed_motion.template head<3>().dot(f.angular()) + packed_motion.template tail<3>().dot(f.linear());
}

}  // namespace heavesim
