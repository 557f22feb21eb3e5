#pragma once
// The constraint equations Phi(q, t) = 0 of a model, their Jacobian J = dPhi/dq (in
// velocity coordinates, m x nv), the velocity target nu = -dPhi/dt (J v = nu), the
// acceleration bias gamma = -dJ/dt v - d2Phi/dt2 (J qdd = gamma), and the forces they
// exert. Only drivers and expression constraints depend on t explicitly. Sign
// convention for multipliers lambda:
//   M qdd + C(q, v) = tau + J^T lambda,    J qdd = gamma.
#include "kernel/model/data.hpp"

namespace heavesim {

/// Phi(q, t) (m or rad; an expression's in its own unit); requires the position stage.
/// Coupler, joint-coordinate driver and expression rows read q.
void constraint_residual(const Model& model, const Data& data, const VectorX& q, double t,
                         Eigen::Ref<VectorX> residual);

/// J (m x nv) at time t [s]; requires the position stage. An expression constraint's
/// row df/dx may depend on t (f = s - t theta); the q it reads is data.q, the position
/// stage's.
void constraint_jacobian(const Model& model, const Data& data, double t, Eigen::Ref<MatrixX> jacobian);

/// nu = -dPhi/dt (m): J v = nu on the constraint manifold; zero but for drivers and
/// expression constraints (whose -df/dt may depend on q: it reads data.q); requires the
/// position stage.
void constraint_velocity_target(const Model& model, const Data& data, double t, Eigen::Ref<VectorX> target);

/// gamma (m): J qdd = gamma, i.e. minus the part of d2Phi/dt2 that does not depend on
/// qdd; requires the velocity stage (an expression row reads data.q and data.v).
void constraint_bias(const Model& model, const Data& data, double t, Eigen::Ref<VectorX> bias);

/// The wrench (world, about the origin) that constraint c exerts on its link_b for
/// the multipliers lambda (all rows); link_a receives the opposite wrench. Zero for couplers,
/// joint-coordinate drivers and expression constraints (they act on joint coordinates).
Force constraint_wrench(const Model& model, const Data& data, const Constraint& constraint, const VectorX& lambda);

/// Adds J^T lambda as loads at time t [s]: constraint wrenches on the links (f_ext) and
/// coupler, joint-coordinate driver and expression forces on the joint coordinates (tau).
void add_constraint_loads(const Model& model, const Data& data, double t, const VectorX& lambda,
                          AlignedVector<Force>& external_forces_world, VectorX& tau);

/// Whether a driver's coordinate is an angle [rad] (its multiplier a torque, N m) rather
/// than a length [m] (a force, N): angle drivers, and joint drivers of a rotation
/// coordinate (revolute, universal, a cylindrical joint's coordinate 0).
bool driver_is_angular(const Model& model, const Constraint& driver);

/// The world placements of a constraint's frames A and B; requires the position stage.
Transform constraint_frame_a(const Data& data, const Constraint& constraint);
Transform constraint_frame_b(const Data& data, const Constraint& constraint);

}  // namespace heavesim
