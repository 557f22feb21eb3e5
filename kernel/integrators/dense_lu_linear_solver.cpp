#include "kernel/integrators/dense_lu_linear_solver.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/LU>
#include <limits>
#include <memory>
#include <new>

#include "kernel/integrators/sundials_support.hpp"

namespace heavesim::sundials {
namespace {

constexpr double kNoFactor = std::numeric_limits<double>::quiet_NaN();

struct DenseLu {
  DenseLu(Eigen::Index size, const NewtonMatrixParts& parts)
      : factor(size),
        right_hand_side(size),
        parts(parts),
        newton_matrix(parts.residual_y ? size : 0, parts.residual_y ? size : 0) {}
  Eigen::PartialPivLU<MatrixX> factor;  // LU of the last matrix set up
  VectorX right_hand_side;              // b's copy when x is b (Eigen's in-place permutation allocates)
  NewtonMatrixParts parts;              // empty: solve with the matrix of the last setup
  MatrixX newton_matrix;                // dF/dy + cj dF/dy' re-formed at a new cj
  double factored_cj = kNoFactor;       // the cj of `factor` (with parts)
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

/// Factors `matrix` into lu.factor (its own storage: same size, no allocation).
template <typename Matrix>
int factorize(DenseLu& lu, const Matrix& matrix) {
  lu.factor.compute(matrix);
  // An exactly zero pivot is a singular matrix, a recoverable failure as for
  // SUNLinSol_Dense (its GETRF returns the pivot's index). Partial pivoting takes the
  // largest entry of the column, so a zero pivot means a zero column below the diagonal.
  const auto pivots = lu.factor.matrixLU().diagonal();
  for (Eigen::Index k = 0; k < pivots.size(); ++k)
    if (pivots[k] == 0.0) return lu.last_flag = SUNLS_LUFACT_FAIL;
  return lu.last_flag = SUNLS_SUCCESS;
}

int setup(SUNLinearSolver solver, SUNMatrix matrix) {
  DenseLu& lu = content(solver);
  if (SUNMatGetID(matrix) != SUNMATRIX_DENSE || SUNDenseMatrix_Rows(matrix) != lu.factor.rows() ||
      SUNDenseMatrix_Columns(matrix) != lu.factor.rows())
    return lu.last_flag = SUNLS_ILL_INPUT;
  // The matrix IDA just filled is dF/dy + cj dF/dy' at the current cj.
  const int flag = factorize(lu, dense(matrix));
  lu.factored_cj = lu.parts.residual_y && flag == SUNLS_SUCCESS ? lu.parts.current_cj(lu.parts.user_data) : kNoFactor;
  return flag;
}

int solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  DenseLu& lu = content(solver);
  if (lu.parts.residual_y) {
    const double cj = lu.parts.current_cj(lu.parts.user_data);
    const bool refreshed = lu.parts.refresh && lu.parts.refresh(lu.parts.user_data);
    if (cj != lu.factored_cj || refreshed) {  // NaN (no factor) never equals cj
      lu.newton_matrix.noalias() = *lu.parts.residual_y + cj * *lu.parts.residual_yp;
      lu.factored_cj = kNoFactor;
      if (factorize(lu, lu.newton_matrix) != SUNLS_SUCCESS) return lu.last_flag;  // recoverable
      lu.factored_cj = cj;
    }
  }
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
  *real_words = static_cast<long>(n * n + content(solver).newton_matrix.size());
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

SUNLinearSolver make_dense_lu_linear_solver(SUNMatrix matrix, SUNContext context, const NewtonMatrixParts& parts) {
  auto lu = std::make_unique<DenseLu>(SUNDenseMatrix_Rows(matrix), parts);
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
