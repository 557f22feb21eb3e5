#pragma once
// Spatial motion and force vectors in Featherstone's [angular; linear] order.
//
// A Motion holds (omega, v): angular velocity and the linear velocity of the point
// at the frame origin. A Force holds (n, f): moment about the frame origin and force.
// Both are expressed in some frame that the owner names (X_world, ..._link, ...).
// Reference: R. Featherstone, Rigid Body Dynamics Algorithms (2008), ch. 2.
#include "kernel/spatial/types.hpp"

namespace heavesim {

class Force;

class Motion {
 public:
  Motion() : data_(Vector6::Zero()) {}
  Motion(const Vector3& angular, const Vector3& linear) { data_ << angular, linear; }
  explicit Motion(const Vector6& data) : data_(data) {}
  static Motion Zero() { return Motion(); }

  auto angular() { return data_.head<3>(); }
  auto angular() const { return data_.head<3>(); }
  auto linear() { return data_.tail<3>(); }
  auto linear() const { return data_.tail<3>(); }
  Vector6& vector() { return data_; }
  const Vector6& vector() const { return data_; }

  Motion operator+(const Motion& other) const { return Motion(Vector6(data_ + other.data_)); }
  Motion operator-(const Motion& other) const { return Motion(Vector6(data_ - other.data_)); }
  Motion operator-() const { return Motion(Vector6(-data_)); }
  Motion operator*(double s) const { return Motion(Vector6(data_ * s)); }
  Motion& operator+=(const Motion& other) { data_ += other.data_; return *this; }
  Motion& operator-=(const Motion& other) { data_ -= other.data_; return *this; }

  /// Spatial cross product for motions, this x_m m (Featherstone eq. 2.31):
  /// [w x w_m ; w x v_m + v x w_m].
  Motion cross(const Motion& m) const {
    const Vector3 w = angular(), v = linear();
    return Motion(w.cross(m.angular()), w.cross(m.linear()) + v.cross(m.angular()));
  }
  /// Spatial cross product for forces, this x_f f (Featherstone eq. 2.32):
  /// [w x n + v x f ; w x f].
  inline Force cross(const Force& f) const;

  /// Velocity of the point p (same frame as this motion) of the moving body.
  Vector3 point_velocity(const Vector3& p) const { return linear() + angular().cross(p); }

 private:
  Vector6 data_;
};

class Force {
 public:
  Force() : data_(Vector6::Zero()) {}
  Force(const Vector3& angular, const Vector3& linear) { data_ << angular, linear; }
  explicit Force(const Vector6& data) : data_(data) {}
  static Force Zero() { return Force(); }

  /// A force f acting at point p (both in this frame) as a spatial force about the origin.
  static Force at_point(const Vector3& p, const Vector3& f) { return Force(p.cross(f), f); }

  auto angular() { return data_.head<3>(); }
  auto angular() const { return data_.head<3>(); }
  auto linear() { return data_.tail<3>(); }
  auto linear() const { return data_.tail<3>(); }
  Vector6& vector() { return data_; }
  const Vector6& vector() const { return data_; }

  Force operator+(const Force& other) const { return Force(Vector6(data_ + other.data_)); }
  Force operator-(const Force& other) const { return Force(Vector6(data_ - other.data_)); }
  Force operator-() const { return Force(Vector6(-data_)); }
  Force operator*(double s) const { return Force(Vector6(data_ * s)); }
  Force& operator+=(const Force& other) { data_ += other.data_; return *this; }
  Force& operator-=(const Force& other) { data_ -= other.data_; return *this; }

  /// Moment of this force system about the point p (same frame).
  Vector3 moment_about(const Vector3& p) const { return angular() - p.cross(linear()); }

 private:
  Vector6 data_;
};

inline Force Motion::cross(const Force& f) const {
  const Vector3 w = angular(), v = linear();
  return Force(w.cross(f.angular()) + v.cross(f.linear()), w.cross(f.linear()));
}

/// Power of a force on a motion (both in the same frame).
inline double dot(const Motion& m, const Force& f) { return m.vector().dot(f.vector()); }

}  // namespace heavesim
