#pragma once
// Analytical derivatives of inverse dynamics, tau = ID(q, v, qdd), with the external
// forces held fixed in the world (Carpentier & Mansard, "Analytical derivatives of
// rigid body dynamics algorithms", RSS 2018, here in the kernel's world form).
#include "kernel/algorithms/inverse_dynamics.hpp"

namespace heavesim {

/// Fills data.dtau_dq and data.dtau_dv (nv x nv) at (q, v, qdd). Column j of dtau_dq
/// is the derivative along joint coordinate j's tangent: the change of tau when the
/// configuration moves by integrate(q, e_j h) (for plain joints, d/dq_j itself).
/// Leaves the stages and data.tau as rnea(q, v, qdd) does.
///
/// Perturbing coordinate j of joint J moves J's whole subtree rigidly by the world
/// screw s = S_j, so for every link k in that subtree (p = J's parent link):
///   dv_k = s x (v_k - v_p),   da_k = s x (a_k - a_p) + (v_p x s) x (v_k - v_p),
///   d(I m) = s x* (I m) - I (s x m)   for any inertia attached to the subtree,
/// and d tau_i = (s x S_i)^T F_i + S_i^T dF_i. For velocities: dv_k = s,
/// da_k = v_p x s + s x (v_k - v_J). A universal joint's subspace and bias also
/// depend on its own coordinates; those terms (from the joint) are added to its
/// columns. Everything is analytic: no finite differences.
void inverse_dynamics_derivatives(const Model& model, Data& data, const VectorX& q, const VectorX& v,
                                  const VectorX& qdd, ExternalForces external_forces_world = {});

}  // namespace heavesim
