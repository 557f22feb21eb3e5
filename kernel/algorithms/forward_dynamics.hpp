#pragma once
// Forward dynamics of a tree by either of two independent algorithms; they are
// cross-checked in tests (validation K6).
#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/mass_matrix.hpp"

namespace heavesim {

enum class ForwardDynamicsMethod {
  articulated_body,     // ABA, O(n)
  composite_rigid_body  // M = CRBA, C = RNEA(qdd = 0), qdd = M^-1 (tau - C) by Cholesky
};

/// qdd = M^-1 (tau - C) by CRBA + Cholesky on the current stages; fills data.qdd.
const VectorX& composite_rigid_body_forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                                     ExternalForces external_forces_world = {});

/// qdd on the current stages by the chosen method; fills data.qdd.
const VectorX& forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                ExternalForces external_forces_world = {},
                                ForwardDynamicsMethod method = ForwardDynamicsMethod::articulated_body);

}  // namespace heavesim
