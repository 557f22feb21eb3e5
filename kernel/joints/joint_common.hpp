#pragma once
// What every joint type provides (checked at compile time by the variant visitors):
//
//   static constexpr int nq, nv;          configuration and velocity sizes
//   static constexpr const char* type_name;
//   Transform transform(const double* q)  X_J: the joint's child-side frame in its
//                                         parent-side frame
//   MotionSubspace motion_subspace(q)     S (6 x nv): relative spatial velocity of the
//                                         child side is S v, in child-side coordinates
//   Motion bias_acceleration(q, v)        c_J = (dS/dt) v, child-side coordinates;
//                                         evaluated only when has_bias_acceleration
//                                         (Featherstone 2008, eq. 4.13)
//   void configuration_derivative(q, v, qdot)     qdot = N(q) v
//   void integrate(q, v, dt, q_out)       q_out = q "+" v dt, staying on the manifold
//   void difference(q0, q1, dv)           dv such that integrate(q0, dv, 1) = q1
//   void neutral(q), normalize(q)
//
// Raw pointers index into the model-wide q and v vectors; each joint reads nq / nv
// entries from them. Frames: the joint frame's origin is the joint point; axes are
// given in it.
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

}  // namespace heavesim
