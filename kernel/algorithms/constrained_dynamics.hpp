#pragma once
// Forward dynamics of a model with closed loops (index-1 form):
//   [ M  -J^T ] [ qdd    ]   [ tau - C(q, v)             ]
//   [ J   0   ] [ lambda ] = [ gamma                    ]
// solved through the Schur complement on M's Cholesky factor:
//   (J M^-1 J^T) lambda = gamma - J M^-1 (tau - C),  qdd = M^-1 (tau - C + J^T lambda).
// Redundant constraints make J M^-1 J^T singular: lambda is then the minimum-norm
// solution (regularized Cholesky, regularized_symmetric_solver.hpp), the motion stays unique, and the
// reactions along the redundant directions are not unique (Wojtyra 2005).
// Drift is not stabilized here: the explicit methods project after each step and IDA
// integrates the GGL form, which holds Phi = 0 itself.
#include "kernel/algorithms/forward_dynamics.hpp"

namespace heavesim {

/// Regularization of J M^-1 J^T relative to its largest diagonal entry: the
/// multipliers are minimum-norm to ~1e-12 relative where rows are redundant.
inline constexpr double kkt_regularization = 1e-12;

/// qdd (data.qdd) and lambda (data.constraint_multipliers) on the current stages at
/// time t [s] (drivers); also leaves J and gamma in data (rows set aside in
/// data.constraint_row_used zeroed). Without constraints this is CRBA forward dynamics.
const VectorX& constrained_forward_dynamics(const Model& model, Data& data, double t, const VectorX& tau,
                                            ExternalForces external_forces_world = {});

}  // namespace heavesim
