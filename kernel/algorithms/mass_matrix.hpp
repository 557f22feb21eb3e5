#pragma once
// Composite-rigid-body algorithm for the joint-space inertia matrix M(q)
// (Featherstone 2008, table 6.2, world form: composite inertias add directly).
#include "kernel/algorithms/kinematics.hpp"

namespace heavesim {

/// M(q) from the current position stage; fills data.mass_matrix (both triangles).
const MatrixX& mass_matrix(const Model& model, Data& data);

/// Full pipeline crba(model, data, q).
const MatrixX& crba(const Model& model, Data& data, const VectorX& q);

}  // namespace heavesim
