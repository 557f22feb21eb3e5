#pragma once
// A SUNDIALS linear solver that keeps IDA's Newton matrix G = dF/dy + cj dF/dy' current
// between IDA's own evaluations of it. IDA forms G when it judges the old one too stale
// (cj outside 0.053 to 19 of the cj it was formed at, as IdaIntegrator sets dcj = 0.9 for
// this solver; IDA's default range is 0.6 to 1.67; or after a failed iteration) and
// solves with the old one otherwise (modified Newton). This solver wraps a matrix-based
// solver (the dense LU, KLU) and, before a solve, re-forms G from the system's parts of
// the last evaluation and has the inner solver factor it again when
//   - the current cj differs from the cj of the last factorization by more than
//     kCjChangeSolvedWithTheFactor (within it, the factor's solution is scaled as IDA
//     scales a stale one), or
//   - the system refreshed the parts' cheap blocks (a loop's J turned since).
// Re-forming costs a sum and a factorization; evaluating the parts again costs the
// dynamics' derivatives. As CVODE re-forms I - gamma J from a saved J without evaluating J
// again (Hindmarsh et al. 2005). Why IDA needs it with position multipliers:
// docs/physics/constraints-and-integration.md §5, "Keeping Newton's matrix current".
//
// The solver applies IDA's own correction for a stale cj (scaling the solution by
// 2 / (1 + cj / cj_old)) itself, only where it solved with an older cj's factor, so IDA's
// must be switched off (IDASetLinearSolutionScaling).
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

namespace heavesim::sundials {

/// Within this relative change of cj from the factored one (and without a refresh), the
/// solver solves with the factor it has and scales the solution by 2 / (1 + cj / cj_factored),
/// as IDA does for a stale matrix; beyond it, it re-forms and re-factors. Why 0.3:
/// docs/physics/constraints-and-integration.md §5 (the 3-hour H1 run: 41,301 factorizations
/// -> 13,208 for 2 % more residuals at the same accuracy).
inline constexpr double kCjChangeSolvedWithTheFactor = 0.3;

/// What the solver asks the integrator: the cj IDA solves with now, whether the parts'
/// cheap blocks changed, and the matrix G at a given cj. Called from SUNDIALS' C code:
/// none may throw.
struct NewtonMatrixSource {
  double (*current_cj)(void* user_data) = nullptr;
  /// Brings the parts' cheap blocks up to date (may be null); true when it changed them.
  bool (*refresh)(void* user_data) = nullptr;
  /// Writes dF/dy + cj dF/dy' of the parts into `matrix` (IDA's matrix, same pattern).
  void (*form)(void* user_data, double cj, SUNMatrix matrix) = nullptr;
  void* user_data = nullptr;
};

/// Wraps `inner` (not null; owned by the wrapper from its return on, and freed with it; if
/// this throws, `inner` stays the caller's). `source.current_cj` and `source.form` must
/// be set. setup() is the inner setup (IDA has just evaluated G at the current cj);
/// solve() re-forms and re-factors first when cj moved beyond kCjChangeSolvedWithTheFactor
/// of the factored cj or `source.refresh` returned true (otherwise it solves with the factor
/// and scales); a failed re-factorization returns the inner setup's flag (recoverable for a zero
/// pivot, as for a failed setup). Free it with SUNLinSolFree.
SUNLinearSolver make_reforming_linear_solver(SUNLinearSolver inner, const NewtonMatrixSource& source,
                                             SUNContext context);

}  // namespace heavesim::sundials
