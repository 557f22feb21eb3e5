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

/// Momentum I_i v [N s, N m s] of link i moving with v: rigid plus any added inertia,
/// world coordinates about the world origin; requires update_positions.
inline Force link_momentum(const Model& model, const Data& data, int i, const Motion& v) {
  Force h = data.rigid_inertia_world[i] * v;
  if (model.links[i].added_inertia) h += data.added_inertia_world[i] * v;
  return h;
}

/// Total spatial inertia of link i as a 6x6 matrix (world coordinates about the origin).
inline Matrix6 link_inertia_matrix(const Model& model, const Data& data, int i) {
  Matrix6 I = data.rigid_inertia_world[i].matrix();
  if (model.links[i].added_inertia) I += data.added_inertia_world[i];
  return I;
}

}  // namespace heavesim
