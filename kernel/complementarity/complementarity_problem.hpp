#pragma once
// The linear complementarity problem and its boxed (mixed) form, as every solver in this
// folder reads it, and what every solver returns.
//
//   LCP(M, q):   w = M z + q,   z >= 0,   w >= 0,   z^T w = 0.
//   Boxed MLCP:  w = M z + q,   lo <= z <= hi, and for each row i
//                z_i = lo_i => w_i >= 0,  z_i = hi_i => w_i <= 0,  lo_i < z_i < hi_i => w_i = 0.
// The LCP is the box [0, +inf) on every row; a row with (-inf, +inf) is an equation
// (a bilateral constraint). A friction row i coupled to the normal row j has the box
// [-mu_i z_j, +mu_i z_j] (the friction pyramid's facet scaled by the normal impulse, as
// ODE's findex and Bullet's limitDependency): the bounds depend on the answer, so this is
// no longer an LCP and no pivoting guarantee covers it (docs/physics/complementarity.md).
//
// Units are the caller's: in contact dynamics z are impulses [N s] and w relative
// velocities [m/s], M = J M^-1 J^T [m/(N s^2)]. Nothing here knows of bodies or frames.
#include <optional>
#include <string>

#include "kernel/spatial/types.hpp"

namespace heavesim {

/// Views the solvers read and write: a whole MatrixX / VectorX or a block of a larger
/// one (e.g. the top-left n x n of a workspace sized for the most contacts), so that a
/// caller whose problem size changes from step to step never reallocates.
using ConstMatrixView = Eigen::Ref<const MatrixX>;
using ConstVectorView = Eigen::Ref<const VectorX>;
using VectorView = Eigen::Ref<VectorX>;
using ConstIndexView = Eigen::Ref<const Eigen::VectorXi>;

/// One complementarity problem, by reference (the caller owns the arrays). No bounds:
/// lo = 0, hi = +inf (the plain LCP). friction_normal[i] >= 0 makes row i a friction row
/// of the normal row friction_normal[i] with coefficient friction_coefficient[i] (both
/// absent: no friction rows; -1 in friction_normal: an ordinary row).
struct ComplementarityProblem {
  ConstMatrixView M;
  ConstVectorView q;
  std::optional<ConstVectorView> lower = std::nullopt;
  std::optional<ConstVectorView> upper = std::nullopt;
  std::optional<ConstIndexView> friction_normal = std::nullopt;
  std::optional<ConstVectorView> friction_coefficient = std::nullopt;

  int size() const { return static_cast<int>(q.size()); }
  bool boxed() const { return lower.has_value() || upper.has_value() || has_friction(); }
  bool has_friction() const { return friction_normal.has_value(); }
  bool is_friction_row(int i) const { return friction_normal && (*friction_normal)[i] >= 0; }
  /// The box of row i at the answer z (friction rows: +-mu_i max(z_normal, 0)).
  double lower_bound(int i, const ConstVectorView& z) const;
  double upper_bound(int i, const ConstVectorView& z) const;
};

enum class ComplementarityStatus {
  solved,           ///< the residual is at most the tolerance
  ray_termination,  ///< Lemke: no blocking row for the entering column (no solution for copositive-plus M, or outside the class)
  iteration_limit,  ///< the pivot cap was reached (Lemke, Dantzig)
  not_converged,    ///< an iterative solver ran out of sweeps, or a pivoting answer misses the tolerance (friction boxes)
  diverged,         ///< an iterative solver's iterate grew without bound or became non-finite
  singular_pivot,   ///< a zero or negative pivot: Dantzig's active block is singular, or a zero diagonal for Gauss-Seidel
  unsupported,      ///< the solver does not take this form (Dantzig: non-symmetric M; Lemke: friction rows or free rows)
  invalid_input,    ///< the problem itself is wrong (sizes, non-finite entries, lo > hi, mu < 0): see message
};
const char* to_string(ComplementarityStatus status);

enum class ComplementaritySolver { lemke, dantzig, projected_gauss_seidel, gauss_seidel };
const char* to_string(ComplementaritySolver solver);

struct ComplementarityResult {
  ComplementarityStatus status = ComplementarityStatus::invalid_input;
  ComplementaritySolver solver = ComplementaritySolver::lemke;  ///< which solver produced this answer
  int pivots = 0;       ///< pivoting solvers: pivots done (Lemke counts z0 entering and leaving)
  int iterations = 0;   ///< iterative solvers: sweeps done
  int pivot_limit = 0;  ///< the cap that was in force (pivots or sweeps)
  /// |z - mid(lo, hi, z - w)|_inf: the natural-map residual, zero exactly at a solution
  /// (for the LCP it is |min(z, w)|_inf); w = M z + q evaluated afresh from z.
  double residual_absolute = 0.0;
  /// residual_absolute / |q|_inf (|q|_inf = 0: / 1), Siconos' and FCLIB's scaling.
  double residual = 0.0;
  int attempts = 1;     ///< fallback chain: solvers tried, the successful one included
  std::string message;  ///< failures: names the row, entry or condition; solved by a fallback chain: the solvers that failed first; else empty
  bool solved() const { return status == ComplementarityStatus::solved; }
};

/// invalid_input with a message naming the first bad entry, or solved (= usable) if the
/// problem is well formed: square M, sizes agree, finite M and q, lo <= hi (no NaN),
/// friction normal indices in range and not the row itself, mu finite and >= 0.
ComplementarityResult validate(const ComplementarityProblem& problem);

/// False, with `result` made invalid_input naming the sizes, when a workspace sized for
/// `capacity` rows cannot hold the `rows_needed` a solver needs, or z is not the problem's
/// size n: the one check every solver makes before it touches its workspace.
bool fits_workspace(ComplementarityResult& result, const char* solver, int capacity, int rows_needed, Eigen::Index z_size,
                    int n);

/// Fills w = M z + q (w: n entries, e.g. the head of a larger workspace vector) and sets
/// result.residual and result.residual_absolute; allocation-free.
void evaluate_residual(const ComplementarityProblem& problem, const ConstVectorView& z, VectorView w,
                       ComplementarityResult& result);

}  // namespace heavesim
