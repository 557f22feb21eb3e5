// The dense LU linear solver IDA uses (kernel/integrators/dense_lu_linear_solver.hpp)
// against SUNDIALS' own dense solver (SUNLinSol_Dense, a separate implementation of
// the same elimination) and against the residual of the system it solves.
#include <gtest/gtest.h>

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <random>

#include "kernel/integrators/dense_lu_linear_solver.hpp"
#include "kernel/integrators/sundials_support.hpp"
#include "tests/kernel/sundials_dense_reference.hpp"

namespace heavesim {
namespace {

struct DenseSystem {
  sundials::Context context;
  SUNMatrix matrix;
  N_Vector rhs, solution;
  explicit DenseSystem(int n)
      : matrix(SUNDenseMatrix(n, n, context)), rhs(N_VNew_Serial(n, context)), solution(N_VNew_Serial(n, context)) {}
  ~DenseSystem() {
    SUNMatDestroy(matrix);
    N_VDestroy(rhs);
    N_VDestroy(solution);
  }
  Eigen::Map<MatrixX> A() {
    return Eigen::Map<MatrixX>(SUNDenseMatrix_Data(matrix), SUNDenseMatrix_Rows(matrix), SUNDenseMatrix_Columns(matrix));
  }
};

TEST(DenseLuLinearSolver, SolvesAsSundialsDenseSolverDoes) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  // Sizes about those of the Newton matrices IDA meets (a slider-crank's 10, the H1 rig's
  // few tens) and an odd one past Eigen's blocking size; unsymmetric, with a pivot
  // search that must swap rows (small diagonal).
  for (int n : {1, 2, 10, 33, 70}) {
    MatrixX A = MatrixX::NullaryExpr(n, n, [&] { return entry(random); });
    A.diagonal() *= 1e-3;
    const VectorX b = VectorX::NullaryExpr(n, [&] { return entry(random); });

    DenseSystem system(n);
    system.A() = A;
    sundials::map(system.rhs) = b;
    SUNLinearSolver solver = sundials::make_dense_lu_linear_solver(system.matrix, system.context);
    ASSERT_EQ(SUNLinSolGetType(solver), SUNLINEARSOLVER_DIRECT);
    ASSERT_EQ(SUNLinSolSetup(solver, system.matrix), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(solver, system.matrix, system.solution, system.rhs, 0.0), SUNLS_SUCCESS);
    const VectorX x = sundials::map(system.solution);

    // Backward stable: a residual of round-off size relative to |A| |x|.
    const double residual = (A * x - b).norm() / (A.norm() * x.norm());
    EXPECT_LT(residual, 1e-14) << "n = " << n;
    // The same elimination as SUNDIALS' solver: agreement to round-off times the condition.
    const double condition = A.jacobiSvd().singularValues()(0) / A.jacobiSvd().singularValues()(n - 1);
    const VectorX reference = testing::sundials_dense_solution(A, b);
    EXPECT_LT((x - reference).norm() / reference.norm(), 1e-15 * condition) << "n = " << n << ", cond " << condition;

    // The interface allows the same vector as right-hand side and solution (IDA 6.4 passes
    // a vector of its own as x).
    ASSERT_EQ(SUNLinSolSolve(solver, system.matrix, system.rhs, system.rhs, 0.0), SUNLS_SUCCESS);
    EXPECT_EQ(VectorX(sundials::map(system.rhs)), x) << "n = " << n;
    SUNLinSolFree(solver);
  }
}

TEST(DenseLuLinearSolver, ZeroPivotIsARecoverableFailureAsForSundialsDense) {
  const int n = 5;
  MatrixX A = MatrixX::Identity(n, n) + MatrixX::Constant(n, n, 0.25);
  A.col(3).setZero();  // singular: elimination meets a zero column
  DenseSystem ours(n), theirs(n);
  ours.A() = A;
  theirs.A() = A;
  SUNLinearSolver solver = sundials::make_dense_lu_linear_solver(ours.matrix, ours.context);
  SUNLinearSolver reference = SUNLinSol_Dense(theirs.rhs, theirs.matrix, theirs.context);
  const int reference_flag = SUNLinSolSetup(reference, theirs.matrix);
  EXPECT_GT(reference_flag, 0);  // SUNDIALS: recoverable, the step is retried
  EXPECT_EQ(SUNLinSolSetup(solver, ours.matrix), SUNLS_LUFACT_FAIL);
  EXPECT_EQ(SUNLinSolLastFlag(solver), SUNLS_LUFACT_FAIL);
  // A matrix of another size than the one the solver was made for is refused.
  DenseSystem other(n + 1);
  other.A().setIdentity();
  EXPECT_EQ(SUNLinSolSetup(solver, other.matrix), SUNLS_ILL_INPUT);
  SUNLinSolFree(solver);
  SUNLinSolFree(reference);
}

}  // namespace
}  // namespace heavesim
