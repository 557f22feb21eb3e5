#include "kernel/integrators/reforming_linear_solver.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <new>

namespace heavesim::sundials {
namespace reforming {  // the file's own names, apart from its unity-build neighbours'
namespace {

constexpr double kNoFactor = std::numeric_limits<double>::quiet_NaN();  // equals no cj

struct Reforming {
  SUNLinearSolver inner = nullptr;
  NewtonMatrixSource source;
  double factored_cj = kNoFactor;  // the cj of the inner solver's factor
};

Reforming& content(SUNLinearSolver solver) { return *static_cast<Reforming*>(solver->content); }

SUNLinearSolver_Type type(SUNLinearSolver solver) { return SUNLinSolGetType(content(solver).inner); }
SUNLinearSolver_ID custom(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver solver) {
  content(solver).factored_cj = kNoFactor;
  return SUNLinSolInitialize(content(solver).inner);
}

/// The inner setup's flag as one IDA's solve understands: idaLsSolve takes a positive flag
/// it does not list for success (and would use x = 0), so any other failure becomes
/// SUNDIALS' generic recoverable or unrecoverable one.
int as_solve_flag(int setup_flag) {
  switch (setup_flag) {
    case SUNLS_SUCCESS:
    case SUNLS_LUFACT_FAIL:
    case SUNLS_PACKAGE_FAIL_REC:
    case SUNLS_PACKAGE_FAIL_UNREC:
    case SUNLS_MEM_NULL:
    case SUNLS_ILL_INPUT:
    case SUNLS_MEM_FAIL:
      return setup_flag;
    default:
      return setup_flag > 0 ? SUNLS_PACKAGE_FAIL_REC : SUNLS_PACKAGE_FAIL_UNREC;
  }
}

int setup(SUNLinearSolver solver, SUNMatrix matrix) {
  Reforming& state = content(solver);
  const int flag = SUNLinSolSetup(state.inner, matrix);
  state.factored_cj = flag == SUNLS_SUCCESS ? state.source.current_cj(state.source.user_data) : kNoFactor;
  return flag;
}

int solve(SUNLinearSolver solver, SUNMatrix matrix, N_Vector x, N_Vector b, realtype tolerance) {
  Reforming& state = content(solver);
  const NewtonMatrixSource& source = state.source;
  const double cj = source.current_cj(source.user_data);
  const bool refreshed = source.refresh && source.refresh(source.user_data);
  const double cj_ratio = cj / state.factored_cj;  // NaN without a factor
  if (!refreshed && std::abs(cj_ratio - 1.0) <= kCjChangeSolvedWithTheFactor) {
    // IDA's own correction of a solution for a stale cj, as DASSL's (Brenan, Campbell &
    // Petzold 1996): the factored matrix's solution scaled by 2 / (1 + cj / cj_factored).
    const int flag = SUNLinSolSolve(state.inner, matrix, x, b, tolerance);
    if (cj_ratio != 1.0) N_VScale(2.0 / (1.0 + cj_ratio), x, x);
    return flag;
  }
  source.form(source.user_data, cj, matrix);
  state.factored_cj = kNoFactor;
  if (const int flag = SUNLinSolSetup(state.inner, matrix); flag != SUNLS_SUCCESS) return as_solve_flag(flag);
  state.factored_cj = cj;
  return SUNLinSolSolve(state.inner, matrix, x, b, tolerance);
}

sunindextype last_flag(SUNLinearSolver solver) { return SUNLinSolLastFlag(content(solver).inner); }

int space(SUNLinearSolver solver, long* real_words, long* integer_words) {
  return SUNLinSolSpace(content(solver).inner, real_words, integer_words);
}

int free_solver(SUNLinearSolver solver) {
  if (!solver) return SUNLS_SUCCESS;
  if (solver->content) {
    SUNLinSolFree(content(solver).inner);
    delete static_cast<Reforming*>(solver->content);
    solver->content = nullptr;
  }
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

}  // namespace
}  // namespace reforming

SUNLinearSolver make_reforming_linear_solver(SUNLinearSolver inner, const NewtonMatrixSource& source,
                                             SUNContext context) {
  auto state = std::make_unique<reforming::Reforming>(reforming::Reforming{inner, source});
  SUNLinearSolver solver = SUNLinSolNewEmpty(context);
  if (!solver) throw std::bad_alloc();
  solver->content = state.release();
  solver->ops->gettype = reforming::type;
  solver->ops->getid = reforming::custom;
  solver->ops->initialize = reforming::initialize;
  solver->ops->setup = reforming::setup;
  solver->ops->solve = reforming::solve;
  solver->ops->lastflag = reforming::last_flag;
  solver->ops->space = reforming::space;
  solver->ops->free = reforming::free_solver;
  return solver;
}

}  // namespace heavesim::sundials
