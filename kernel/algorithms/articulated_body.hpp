#pragma once
// Articulated-body algorithm, O(n) forward dynamics (Featherstone 2008, table 7.1,
// world form: articulated inertias accumulate without transforms).
#include "kernel/algorithms/inverse_dynamics.hpp"

namespace heavesim {

/// qdd from the current stages for applied joint forces tau (nv) and external
/// forces; fills data.qdd and data.acceleration_world.
const VectorX& articulated_body_forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                                 ExternalForces external_forces_world = {});

/// The wrench each joint transmits, parent on child (data.joint_wrench_world, world axes,
/// about the world origin), from the articulated-body pass of this evaluation:
/// f_i = I^A_i a_i + p^A_i, the force on the handle of the subtree at link i that gives it
/// the acceleration a_i (the articulated-body equation, Featherstone 2008, sec. 7.1): one
/// 6 x 6 product a link instead of an inverse-dynamics pass. It
/// holds for the joint and external forces that pass was given, and only for them: loads
/// added after it (a constraint's) are not in p^A. Returns false, touching nothing,
/// unless the acceleration stage is current and came from that pass in this evaluation
/// (data.articulated_evaluation); marks the reactions' stage otherwise.
bool articulated_body_joint_wrenches(const Model& model, Data& data);

/// Full pipeline aba(model, data, q, v, tau).
const VectorX& aba(const Model& model, Data& data, const VectorX& q, const VectorX& v, const VectorX& tau,
                   ExternalForces external_forces_world = {});

}  // namespace heavesim
