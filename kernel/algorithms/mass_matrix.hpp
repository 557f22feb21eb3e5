#pragma once
// Composite-rigid-body algorithm for the joint-space inertia matrix M(q)
// (Featherstone 2008, table 6.2, world form: composite inertias add directly).
#include "kernel/algorithms/kinematics.hpp"

namespace heavesim {

/// Sizes data.mass_matrix (zeroed) and its Cholesky factor, if they are not sized yet:
/// mass_matrix() and factorize_mass_matrix() do so at their first call; a system whose
/// every evaluation forms M does so when it is made, so that not even its first
/// evaluation allocates (Data(model) leaves the dense matrices to their first use).
void size_mass_matrix(const Model& model, Data& data);

/// M(q) from the current position stage; fills data.mass_matrix (both triangles).
const MatrixX& mass_matrix(const Model& model, Data& data);

/// M(q) and its Cholesky factor (data.mass_matrix, data.mass_matrix_cholesky) at the
/// current position stage, computed once per configuration: a second call on the same
/// positions returns the factor held (StageMarker::mass_factor).
const Eigen::LLT<MatrixX>& factorize_mass_matrix(const Model& model, Data& data);

/// Full pipeline crba(model, data, q).
const MatrixX& crba(const Model& model, Data& data, const VectorX& q);

}  // namespace heavesim
