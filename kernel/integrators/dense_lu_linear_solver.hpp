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

namespace heavesim::sundials {

/// A direct solver for the square SUNDenseMatrix `matrix` (its size is fixed here).
/// setup() returns SUNLS_LUFACT_FAIL, a recoverable failure (IDA then retries with a
/// smaller step), when a pivot is exactly zero, as SUNLinSol_Dense does; solve() gives
/// x = A^-1 b. Free it with SUNLinSolFree.
SUNLinearSolver make_dense_lu_linear_solver(SUNMatrix matrix, SUNContext context);

}  // namespace heavesim::sundials
