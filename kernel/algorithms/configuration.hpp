#pragma once
// Operations on the configuration manifold (unit quaternions inside q).
#include "kernel/model/model.hpp"

namespace heavesim {

/// qdot = N(q) v (nq); quaternion rates include a weak pull back to unit norm.
void configuration_derivative(const Model& model, const VectorX& q, const VectorX& v, Eigen::Ref<VectorX> qdot);

/// q_out = q "+" v dt, joint by joint on the manifold (quaternions stay unit).
void integrate_configuration(const Model& model, const VectorX& q, const VectorX& v, double dt, VectorX& q_out);

/// dv (nv) such that integrate_configuration(q0, dv, 1) = q1 (rotation vectors for rotations).
void configuration_difference(const Model& model, const VectorX& q0, const VectorX& q1, VectorX& dv);

/// Renormalizes every quaternion in q.
void normalize_configuration(const Model& model, VectorX& q);

}  // namespace heavesim
