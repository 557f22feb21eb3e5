#pragma once
// Bringing a state onto the constraint manifold: assembly of a user's approximate
// initial state, and coordinate projection after explicit integration steps
// (Hairer, Lubich & Wanner, Geometric Numerical Integration, IV.4).
//
// Corrections are the smallest in kinetic energy: dq = -M^-1 J^T (J M^-1 J^T)^+ Phi,
// so they do not depend on the units of the coordinates (a plain pseudo-inverse
// would mix radians and metres) and leave motions the constraints allow untouched.
#include <string>
#include <vector>

#include "kernel/model/data.hpp"

namespace heavesim {

struct ProjectionResult {
  bool converged = false;
  int iterations = 0;
  double position_residual = 0.0;  // max |Phi| after the last iteration
  double velocity_residual = 0.0;  // max |J v - nu| after velocity projection
};

/// Newton iterations on Phi(q, t) = 0 until max |Phi| <= tolerance, then v onto
/// J v = nu(t). Leaves the position stage (and J) at the projected q. Allocation-free.
ProjectionResult project_to_constraints(const Model& model, Data& data, double t, VectorX& q, VectorX& v,
                                        double tolerance, int max_iterations);

/// Rank of the constraint Jacobian and the rows that depend on others, found by a
/// rank-revealing (column-pivoted) QR of J^T at the current position stage.
struct ConstraintRank {
  int rows = 0;
  int rank = 0;
  std::vector<int> redundant_rows;  // row indices; the reactions along them are not unique
  std::vector<int> inactive_rows;   // rows that do not hold now (joint stops not in contact), ascending
  /// The other rows, ascending: the ones a form keeps.
  std::vector<int> independent_rows() const;
};
/// Relative threshold on the pivots of J^T's column-pivoted QR below which a row counts
/// as depending on the others.
inline constexpr double constraint_rank_threshold = 1e-10;
ConstraintRank analyse_constraint_rank(const Model& model, Data& data, double t,
                                       double relative_threshold = constraint_rank_threshold);

/// The constraint that owns row r, or null.
const Constraint* constraint_of_row(const Model& model, int row);

/// "loop joint 'crown_b': rotation about x" for row r.
std::string describe_constraint_row(const Model& model, int row);

}  // namespace heavesim
