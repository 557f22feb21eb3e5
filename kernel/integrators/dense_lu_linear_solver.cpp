#include "kernel/integrators/dense_lu_linear_solver.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/LU>
#include <memory>
#include <new>

#include "kernel/integrators/sundials_support.hpp"

namespace heavesim::sundials {
namespace {

struct DenseLu {
  explicit DenseLu(Eigen::Index size) : factor(size), right_hand_side(size) {}
  Eigen::PartialPivLU<MatrixX> factor;  // LU of the last matrix set up
  VectorX right_hand_side;              // b's copy when x is b (Eigen's in-place permutation allocates)
  int last_flag = SUNLS_SUCCESS;
};

DenseLu& content(SUNLinearSolver solver) { return *static_cast<DenseLu*>(solver->content); }

Eigen::Map<const MatrixX> dense(SUNMatrix matrix) {
  return Eigen::Map<const MatrixX>(SUNDenseMatrix_Data(matrix), SUNDenseMatrix_Rows(matrix),
                                   SUNDenseMatrix_Columns(matrix));
}

SUNLinearSolver_Type direct(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID custom(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int nothing_to_initialize(SUNLinearSolver solver) { return content(solver).last_flag = SUNLS_SUCCESS; }

int setup(SUNLinearSolver solver, SUNMatrix matrix) {
  DenseLu& lu = content(solver);
  if (SUNMatGetID(matrix) != SUNMATRIX_DENSE || SUNDenseMatrix_Rows(matrix) != lu.factor.rows() ||
      SUNDenseMatrix_Columns(matrix) != lu.factor.rows())
    return lu.last_flag = SUNLS_ILL_INPUT;
  lu.factor.compute(dense(matrix));  // copies into the factor's own storage: same size, no allocation
  // An exactly zero pivot is a singular matrix, a recoverable failure as for
  // SUNLinSol_Dense (its GETRF returns the pivot's index). Partial pivoting takes the
  // largest entry of the column, so a zero pivot means a zero column below the diagonal.
  const auto pivots = lu.factor.matrixLU().diagonal();
  for (Eigen::Index k = 0; k < pivots.size(); ++k)
    if (pivots[k] == 0.0) return lu.last_flag = SUNLS_LUFACT_FAIL;
  return lu.last_flag = SUNLS_SUCCESS;
}

int solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  DenseLu& lu = content(solver);
  Eigen::Map<VectorX> solution = map(x);
  if (N_VGetArrayPointer(x) == N_VGetArrayPointer(b)) {
    lu.right_hand_side = map(b);
    solution = lu.factor.solve(lu.right_hand_side);
  } else {
    solution = lu.factor.solve(map(b));
  }
  return lu.last_flag = SUNLS_SUCCESS;
}

sunindextype last_flag(SUNLinearSolver solver) { return content(solver).last_flag; }

int space(SUNLinearSolver solver, long* real_words, long* integer_words) {
  const Eigen::Index n = content(solver).factor.rows();
  *real_words = static_cast<long>(n * n);
  *integer_words = static_cast<long>(2 * n);  // the row transpositions and the permutation
  return SUNLS_SUCCESS;
}

int free_solver(SUNLinearSolver solver) {
  if (!solver) return SUNLS_SUCCESS;
  delete static_cast<DenseLu*>(solver->content);
  solver->content = nullptr;
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver make_dense_lu_linear_solver(SUNMatrix matrix, SUNContext context) {
  auto lu = std::make_unique<DenseLu>(SUNDenseMatrix_Rows(matrix));
  SUNLinearSolver solver = SUNLinSolNewEmpty(context);
  if (!solver) throw std::bad_alloc();
  solver->content = lu.release();
  solver->ops->gettype = direct;
  solver->ops->getid = custom;
  solver->ops->initialize = nothing_to_initialize;
  solver->ops->setup = setup;
  solver->ops->solve = solve;
  solver->ops->lastflag = last_flag;
  solver->ops->space = space;
  solver->ops->free = free_solver;
  return solver;
}

}  // namespace heavesim::sundials
