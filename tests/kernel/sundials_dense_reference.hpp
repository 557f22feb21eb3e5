#pragma once
// The independent reference of the linear-solver tests: x from SUNDIALS' own dense solver
// (SUNLinSol_Dense, its column-oriented GETRF/GETRS) for A x = b.
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <gtest/gtest.h>

#include "kernel/integrators/sundials_support.hpp"

namespace heavesim::testing {

inline VectorX sundials_dense_solution(const MatrixX& A, const VectorX& b) {
  const int n = static_cast<int>(A.rows());
  sundials::Context context;
  SUNMatrix matrix = SUNDenseMatrix(n, n, context);
  N_Vector rhs = N_VNew_Serial(n, context), solution = N_VNew_Serial(n, context);
  Eigen::Map<MatrixX>(SUNDenseMatrix_Data(matrix), n, n) = A;  // factored in place: a copy
  sundials::map(rhs) = b;
  SUNLinearSolver solver = SUNLinSol_Dense(rhs, matrix, context);
  EXPECT_EQ(SUNLinSolSetup(solver, matrix), SUNLS_SUCCESS);
  EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
  const VectorX x = sundials::map(solution);
  SUNLinSolFree(solver);
  N_VDestroy(rhs);
  N_VDestroy(solution);
  SUNMatDestroy(matrix);
  return x;
}

}  // namespace heavesim::testing
