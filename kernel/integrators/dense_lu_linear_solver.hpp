#pragma once
// A SUNDIALS direct linear solver for a SUNDenseMatrix that factors with Eigen's
// partial-pivoting LU (the same algorithm as SUNDIALS' own dense solver: Gaussian
// elimination with row pivoting on the largest entry, Golub & Van Loan 2013, alg. 3.4.1).
// Why not SUNLinSol_Dense: its GETRS is column-by-column scalar loops, and IDA solves
// with it at every Newton iteration; Eigen's blocked, vectorized triangular solves
// are 2.1x faster at n = 20 and 2.9x at n = 30 on this machine (docs/performance.md,
// 2026-11-29). Its factorization is blocked too.
//
// The matrix stays a SUNDenseMatrix, so that IDA's difference-quotient Jacobian
// (which needs that type) and a system's own Newton matrix both fill it. The factor
// lives in the solver, sized once at creation: setup and solve allocate nothing.
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "kernel/spatial/types.hpp"

namespace heavesim::sundials {

/// IDA's Newton matrix G = dF/dy + cj dF/dy' as its two parts (a system's own
/// evaluation, DaeSystem::jacobian), and where to read the cj IDA solves with now.
/// The caller owns the matrices and keeps them alive as long as the solver; with
/// residual_y set, residual_yp and current_cj must be set too.
struct NewtonMatrixParts {
  const MatrixX* residual_y = nullptr;   // dF/dy at the last evaluation
  const MatrixX* residual_yp = nullptr;  // dF/dy' at the last evaluation
  double (*current_cj)(void* user_data) = nullptr;
  /// Brings the parts' cheap blocks up to date (may be null); true when it changed them.
  /// Must not throw (it is called from SUNDIALS).
  bool (*refresh)(void* user_data) = nullptr;
  void* user_data = nullptr;
};

/// A direct solver for the square SUNDenseMatrix `matrix` (its size is fixed here).
/// setup() returns SUNLS_LUFACT_FAIL, a recoverable failure (IDA then retries with a
/// smaller step), when a pivot is exactly zero, as SUNLinSol_Dense does (and so does a
/// solve() that re-forms the matrix, below); solve() gives x = A^-1 b. Free it with
/// SUNLinSolFree.
///
/// With `parts`, solve() first re-forms and factors G from the parts of the last
/// evaluation when the current cj is not the cj of the last factorization or when
/// `parts.refresh` changed them (as CVODE re-forms I - gamma J from a saved J without
/// evaluating J again). The solution is then
/// for the matrix of this step, and IDA's own correction for a changed cj (scaling the
/// solution by 2 / (1 + cj / cj_old)) must be switched off (IDASetLinearSolutionScaling).
SUNLinearSolver make_dense_lu_linear_solver(SUNMatrix matrix, SUNContext context,
                                            const NewtonMatrixParts& parts = {});

}  // namespace heavesim::sundials
