#pragma once
// Recursive Newton-Euler inverse dynamics (Featherstone 2008, table 5.1, world form).
#include <span>

#include "kernel/algorithms/kinematics.hpp"

namespace heavesim {

/// External spatial forces per link (world coordinates, about the world origin),
/// indexed like Model::links; an empty span means none.
using ExternalForces = std::span<const Force>;

/// Inverse dynamics on the current stages (update_positions and update_velocities
/// done): tau = M(q) qdd + C(q, v) - (generalized gravity and external forces).
/// Also fills data.acceleration_world and data.joint_wrench_world, the total wrench
/// f_i exerted by the parent on link i's subtree through joint i:
///   f_i = I_i a_i + v_i x* I_i v_i - f_ext,i - m_i g + sum over children f_c.
const VectorX& inverse_dynamics(const Model& model, Data& data, const VectorX& qdd,
                                ExternalForces external_forces_world = {});

/// Full pipeline rnea(model, data, q, v, qdd): both stages, then inverse dynamics.
const VectorX& rnea(const Model& model, Data& data, const VectorX& q, const VectorX& v, const VectorX& qdd,
                    ExternalForces external_forces_world = {});

}  // namespace heavesim
