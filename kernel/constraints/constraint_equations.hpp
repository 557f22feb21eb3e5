#pragma once
// The constraint equations Phi(q) = 0 of a model, their Jacobian J = dPhi/dq (in
// velocity coordinates, m x nv), the acceleration bias gamma = -dJ/dt v, and the
// forces they exert. Sign convention for multipliers lambda:
//   M qdd + C(q, v) = tau + J^T lambda,    J qdd = gamma.
#include "kernel/model/data.hpp"

namespace heavesim {

/// Phi (m); requires the position stage. Coupler rows read q.
void constraint_residual(const Model& model, const Data& data, const VectorX& q, Eigen::Ref<VectorX> residual);

/// J (m x nv); requires the position stage.
void constraint_jacobian(const Model& model, const Data& data, Eigen::Ref<MatrixX> jacobian);

/// gamma = -dJ/dt v (m), the part of Phi'' that does not depend on qdd; requires the
/// velocity stage.
void constraint_bias(const Model& model, const Data& data, Eigen::Ref<VectorX> bias);

/// The wrench (world, about the origin) that constraint c exerts on its link_b for
/// the multipliers lambda (all rows); link_a receives the opposite wrench. Zero for couplers.
Force constraint_wrench(const Model& model, const Data& data, const Constraint& constraint, const VectorX& lambda);

/// Adds J^T lambda as loads: constraint wrenches on the links (f_ext) and coupler
/// forces on the joint coordinates (tau).
void add_constraint_loads(const Model& model, const Data& data, const VectorX& lambda,
                          AlignedVector<Force>& external_forces_world, VectorX& tau);

/// The world placements of a constraint's frames A and B; requires the position stage.
Transform constraint_frame_a(const Data& data, const Constraint& constraint);
Transform constraint_frame_b(const Data& data, const Constraint& constraint);

}  // namespace heavesim
