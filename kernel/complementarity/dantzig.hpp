#pragma once
// Dantzig's principal pivoting for the boxed MLCP with a symmetric M (Cottle & Dantzig
// 1968; in the incremental form of Baraff 1994 and Smith's ODE dLCP, which Bullet's
// btDantzigSolver copies). Rows are brought in one at a time; row i is "driven": z_i
// moves from 0 in the direction that reduces |w_i| while the rows already clamped
// (w = 0, z inside its box) move with it to keep w = 0, and rows at a bound stay there,
// until w_i = 0, z_i reaches its bound, or another row changes set (a clamped z reaches
// a bound, a bounded row's w reaches 0). The clamped block M_CC is kept as a Cholesky
// factor updated by one row (append) or a rank-one update (removal): O(|C|^2) a change.
//
// Friction rows are brought in after all the others, their box frozen at +-mu times the
// normal row's value at that moment (as ODE does); the residual is then evaluated with
// the final normal values and reported, and a miss is status not_converged.
#include <vector>

#include "kernel/complementarity/complementarity_problem.hpp"

namespace heavesim {

struct DantzigOptions {
  /// A pivot (Schur complement) at most this times the diagonal entry counts as zero: the
  /// clamped block is singular (redundant contacts) and the solve stops with singular_pivot.
  double pivot_tolerance = 1e-12;
  /// Set changes allowed; 0: 20 n.
  int max_pivots = 0;
  /// The answer counts as solved when the relative residual is at most this.
  double tolerance = 1e-10;
};

/// Buffers for problems of up to `size` rows, sized once.
struct DantzigWorkspace {
  explicit DantzigWorkspace(int size = 0);
  int capacity = 0;
  MatrixX cholesky;  ///< lower factor of M_CC (top-left |C| x |C|), C in the order of `clamped`
  /// M's columns of C, contiguous in the order of `clamped` (left |C| columns): the step's
  /// dw = M_:C dz_C is then one matrix-vector product instead of |C| passes over dw.
  MatrixX clamped_columns;
  VectorX w, lower, upper, direction_z, direction_w, gathered;
  VectorX forward;  ///< L^-1 M_Ci of the last drive step, kept for appending row i to C
  VectorX inverse_diagonal;  ///< 1 / L_kk, k < |C|
  std::vector<int> clamped;     ///< C: rows with w = 0
  std::vector<signed char> state;  ///< per row: 0 not yet driven, 1 clamped, 2 at lo, 3 at hi
  std::vector<int> order;
};

/// Solves the boxed MLCP (lo <= 0 <= hi on every row, as the method starts from z = 0;
/// friction boxes always qualify). M must be symmetric (status unsupported otherwise).
ComplementarityResult dantzig(const ComplementarityProblem& problem, DantzigWorkspace& workspace, VectorView z,
                              const DantzigOptions& options = {});

}  // namespace heavesim
