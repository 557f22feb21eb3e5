// The linear solver that re-forms IDA's Newton matrix dF/dy + cj dF/dy' when cj moved by more
// than kCjChangeSolvedWithTheFactor from the factored one (and scales the factor's solution
// as IDA does within it) and after a refresh (kernel/integrators/reforming_linear_solver.hpp), around the dense LU and
// around KLU. Reference: the same matrices formed here and solved by SUNDIALS' own dense
// solver (SUNLinSol_Dense, a separate implementation).
#include <gtest/gtest.h>

#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <random>

#include "kernel/integrators/dense_lu_linear_solver.hpp"
#include "kernel/integrators/reforming_linear_solver.hpp"
#include "kernel/integrators/sundials_support.hpp"
#include "tests/kernel/sundials_dense_reference.hpp"

namespace heavesim {
namespace reforming_linear_solver_test {  // apart from its unity-build neighbours' names

/// The integrator's side: the parts, the cj IDA solves with, a refresh that swaps in other
/// values of dF/dy, and the matrix written densely or on a full compressed-column pattern.
struct Parts {
  MatrixX residual_y, residual_yp, refreshed_residual_y;
  double cj = 1.0;
  bool refresh_pending = false;
  int forms = 0;
  static void write(const MatrixX& values, SUNMatrix matrix) {
    const auto n = values.rows();
    if (SUNMatGetID(matrix) == SUNMATRIX_DENSE) {
      Eigen::Map<MatrixX>(SUNDenseMatrix_Data(matrix), n, n) = values;
      return;
    }
    sunindextype* column_start = SUNSparseMatrix_IndexPointers(matrix);
    sunindextype* row_index = SUNSparseMatrix_IndexValues(matrix);
    double* data = SUNSparseMatrix_Data(matrix);
    for (Eigen::Index c = 0, k = 0; c < n; ++c) {
      column_start[c] = k;
      for (Eigen::Index r = 0; r < n; ++r, ++k) {
        row_index[k] = r;
        data[k] = values(r, c);
      }
    }
    column_start[n] = n * n;
  }
  sundials::NewtonMatrixSource source() {
    return {[](void* self) { return static_cast<Parts*>(self)->cj; },
            [](void* self) {
              auto& parts = *static_cast<Parts*>(self);
              if (!parts.refresh_pending) return false;
              parts.residual_y = parts.refreshed_residual_y;
              parts.refresh_pending = false;
              return true;
            },
            [](void* self, double cj, SUNMatrix matrix) {
              auto& parts = *static_cast<Parts*>(self);
              ++parts.forms;
              write(parts.residual_y + cj * parts.residual_yp, matrix);
            },
            this};
  }
};

void check_reforming(bool sparse) {
  const int n = 10;
  sundials::Context context;
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Parts parts;
  parts.residual_y = MatrixX::NullaryExpr(n, n, [&] { return entry(random); });
  parts.residual_yp = MatrixX::Zero(n, n);
  parts.residual_yp.topLeftCorner(6, 6) =
      MatrixX::Identity(6, 6) + 0.1 * MatrixX::NullaryExpr(6, 6, [&] { return entry(random); });
  parts.refreshed_residual_y = parts.residual_y;
  parts.refreshed_residual_y.bottomRows(2) += 0.2 * MatrixX::NullaryExpr(2, n, [&] { return entry(random); });
  const VectorX b = VectorX::NullaryExpr(n, [&] { return entry(random); });

  N_Vector rhs = N_VNew_Serial(n, context), solution = N_VNew_Serial(n, context);
  SUNMatrix matrix = sparse ? SUNSparseMatrix(n, n, n * n, CSC_MAT, context) : SUNDenseMatrix(n, n, context);
  SUNLinearSolver inner =
      sparse ? SUNLinSol_KLU(rhs, matrix, context) : sundials::make_dense_lu_linear_solver(matrix, context);
  SUNLinearSolver solver = sundials::make_reforming_linear_solver(inner, parts.source(), context);
  EXPECT_EQ(SUNLinSolGetType(solver), SUNLINEARSOLVER_DIRECT);  // IDA treats it as matrix-based

  parts.cj = 40.0;
  Parts::write(parts.residual_y + parts.cj * parts.residual_yp, matrix);  // what IDA's setup hands over
  ASSERT_EQ(SUNLinSolSetup(solver, matrix), SUNLS_SUCCESS);
  const auto solve = [&] {
    sundials::map(rhs) = b;
    EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
    return VectorX(sundials::map(solution));
  };
  const auto relative_error = [&](const VectorX& x, const MatrixX& residual_y) {
    const VectorX reference = testing::sundials_dense_solution(residual_y + parts.cj * parts.residual_yp, b);
    return (x - reference).norm() / reference.norm();
  };
  EXPECT_LT(relative_error(solve(), parts.residual_y), 1e-12);
  EXPECT_EQ(parts.forms, 0) << "the matrix of the setup is for this cj";
  // A new step size within the kept change (10 % < 30 %): the factor of cj = 40 solves, its
  // solution scaled by IDA's 2 / (1 + cj / 40); the reference is that matrix's solution.
  static_assert(sundials::kCjChangeSolvedWithTheFactor > 0.1 && sundials::kCjChangeSolvedWithTheFactor < 0.5);
  parts.cj = 44.0;
  {
    const VectorX stale = testing::sundials_dense_solution(parts.residual_y + 40.0 * parts.residual_yp, b);
    EXPECT_LT((solve() - 2.0 / (1.0 + 44.0 / 40.0) * stale).norm() / stale.norm(), 1e-12);
    EXPECT_GT(relative_error(solve(), parts.residual_y), 1e-3) << "not the current cj's solution";
    EXPECT_EQ(parts.forms, 0);
  }
  parts.cj = 60.0;  // a step size beyond it (50 %): re-formed and factored at the current cj
  EXPECT_LT(relative_error(solve(), parts.residual_y), 1e-12);
  EXPECT_EQ(parts.forms, 1);
  parts.cj = 52.0;  // 13 % below the new factor's cj: that factor (60) serves, not the first
  {
    const VectorX stale = testing::sundials_dense_solution(parts.residual_y + 60.0 * parts.residual_yp, b);
    EXPECT_LT((solve() - 2.0 / (1.0 + 52.0 / 60.0) * stale).norm() / stale.norm(), 1e-12);
    EXPECT_EQ(parts.forms, 1);
  }
  // The band's edges: just inside keeps the factor of 60, just outside re-forms.
  parts.cj = 60.0 * (1.0 - 0.99 * sundials::kCjChangeSolvedWithTheFactor);
  solve();
  EXPECT_EQ(parts.forms, 1);
  parts.cj = 60.0 * (1.0 + 1.01 * sundials::kCjChangeSolvedWithTheFactor);
  EXPECT_LT(relative_error(solve(), parts.residual_y), 1e-12);
  EXPECT_EQ(parts.forms, 2);
  parts.refresh_pending = true;  // the same cj, new dF/dy
  EXPECT_LT(relative_error(solve(), parts.refreshed_residual_y), 1e-12);
  EXPECT_EQ(parts.forms, 3);
  // A re-formed matrix that is singular (a zero column where dF/dy' has none) is the inner
  // solver's recoverable failure; the next solve forms the matrix again.
  const MatrixX good = parts.refreshed_residual_y;
  parts.refreshed_residual_y.col(n - 1).setZero();
  parts.refresh_pending = true;
  const int recoverable = sparse ? SUNLS_PACKAGE_FAIL_REC : SUNLS_LUFACT_FAIL;
  sundials::map(rhs) = b;
  EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), recoverable);
  EXPECT_EQ(parts.forms, 4);
  sundials::map(rhs) = b;  // no refresh, the same cj: the broken factor is not used
  EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), recoverable);
  EXPECT_EQ(parts.forms, 5);
  parts.refreshed_residual_y = good;
  parts.refresh_pending = true;
  EXPECT_LT(relative_error(solve(), good), 1e-12);
  // Without the wrapper the inner solver keeps the factor of its setup (cj = 40, 95 % away): its
  // answer for the current cj is off by far more than round-off.
  SUNLinearSolver plain =
      sparse ? SUNLinSol_KLU(rhs, matrix, context) : sundials::make_dense_lu_linear_solver(matrix, context);
  const double cj = parts.cj;
  parts.cj = 40.0;
  Parts::write(good + parts.cj * parts.residual_yp, matrix);
  ASSERT_EQ(SUNLinSolSetup(plain, matrix), SUNLS_SUCCESS);
  parts.cj = cj;
  sundials::map(rhs) = b;
  ASSERT_EQ(SUNLinSolSolve(plain, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
  EXPECT_GT(relative_error(sundials::map(solution), good), 1e-3);
  SUNLinSolFree(plain);
  SUNLinSolFree(solver);  // frees the inner solver too
  N_VDestroy(rhs);
  N_VDestroy(solution);
  SUNMatDestroy(matrix);
}

TEST(ReformingLinearSolver, AroundTheDenseLuKeepsItsFactorWithinTheBandAndSolvesTheRefreshedMatrix) { check_reforming(false); }

TEST(ReformingLinearSolver, AroundKluKeepsItsFactorWithinTheBandAndSolvesTheRefreshedMatrix) { check_reforming(true); }

}  // namespace reforming_linear_solver_test
}  // namespace heavesim
