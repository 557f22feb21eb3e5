#pragma once
// Pipeline stages (MuJoCo-style): positions, then velocities. Every dynamics
// algorithm reads what these stages leave in Data, so the work is done once per
// state and optional passes can be skipped.
#include "kernel/model/data.hpp"

namespace heavesim {

/// Position stage for configuration q (nq): link placements X_world_link, motion
/// subspaces S in world coordinates, world spatial inertias and weights.
/// Quaternions in q need not be exactly unit: joints use q/|q|.
void update_positions(const Model& model, Data& data, const VectorX& q);

/// Velocity stage for joint velocities v (nv) at configuration q; requires update_positions(q).
/// Fills v_i = v_parent + S_i v_i, c_i = v_i x (S_i v_i) + X_world_link c_J,
/// and the gyroscopic bias forces v_i x* I_i v_i.
void update_velocities(const Model& model, Data& data, const VectorX& q, const VectorX& v);

}  // namespace heavesim
