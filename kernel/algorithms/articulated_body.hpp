#pragma once
// Articulated-body algorithm, O(n) forward dynamics (Featherstone 2008, table 7.1,
// world form: articulated inertias accumulate without transforms).
#include "kernel/algorithms/inverse_dynamics.hpp"

namespace heavesim {

/// qdd from the current stages for applied joint forces tau (nv) and external
/// forces; fills data.qdd and data.acceleration_world.
const VectorX& articulated_body_forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                                 ExternalForces external_forces_world = {});

/// Full pipeline aba(model, data, q, v, tau).
const VectorX& aba(const Model& model, Data& data, const VectorX& q, const VectorX& v, const VectorX& tau,
                   ExternalForces external_forces_world = {});

}  // namespace heavesim
