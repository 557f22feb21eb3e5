#pragma once
// Kinematic analysis of a driven mechanism (docs/physics/kinematics.md): at each time
// point, the configuration q that satisfies the constraint equations Phi(q, t) = 0 (loop
// joints, distances, couplers and drivers), then the velocity v from J v = nu and the
// acceleration a from J a = gamma (constraint_equations.hpp), with no dynamics
// integrated (Haug 1989, ch. 3; Nikravesh 1988, ch. 4).
//
// Newton's method on Phi with the exact Jacobian J (velocity coordinates, steps applied on
// the configuration manifold), a backtracking line search on |Phi|, and MKSim's two
// stopping tests: max |Phi| <= equation_tolerance and max |last step| <=
// solution_tolerance. Every linear solve (Newton step, v, a) is the minimum-norm solution
// in a metric W (minimum_norm_solver.hpp): the mass matrix (minimum kinetic energy: the
// same answer in any units) or the identity. Where the drivers leave directions free
// (fewer independent equations than coordinates) this is the "smoothest" motion; where
// rows repeat (redundant constraints) the solve still has its exact answer. The guess at
// each point is the second-order prediction q(t - h) + h v + h^2/2 a, which keeps the
// solution on the assembly branch it started on.
//
// Allocation-free per time point once the workspace is built.
#include <vector>

#include <Eigen/SVD>

#include "kernel/math/minimum_norm_solver.hpp"
#include "kernel/model/data.hpp"

namespace heavesim {

/// The metric of the minimum-norm solves.
enum class MotionWeighting {
  mass,  // W = M(q): minimum kinetic energy (unit-consistent)
  unit,  // W = I: minimum Euclidean norm of the joint speeds (mixes m and rad)
};

/// The case's `kinematics` section (docs/case-format.md).
struct KinematicSettings {
  double equation_tolerance = 1e-10;  // max |Phi| accepted [m or rad]
  double solution_tolerance = 1e-10;  // max |dq| of the last Newton step accepted [m or rad]
  int max_iterations = 25;            // Newton iterations per time point
  MotionWeighting weighting = MotionWeighting::mass;
  /// Smallest/largest singular value of the (weighted) constraint Jacobian below which a
  /// configuration is reported singular.
  double singular_ratio = 1e-8;
};

/// Rows of J whose QR pivot is below this fraction of the largest count as dependent
/// (the threshold of analyse_constraint_rank).
inline constexpr double kinematic_rank_threshold = 1e-10;

/// Buffers of the analysis, sized once for a model.
struct KinematicWorkspace {
  explicit KinematicWorkspace(const Model& model);
  MinimumNormSolver solver;            // J in the metric W, factorized at the current q
  MatrixX triangle;                    // min(nv, m) x m: the solver's R factor
  Eigen::JacobiSVD<MatrixX> svd;       // its singular values: those of the weighted J
  VectorX step;                        // nv: Newton step
  VectorX trial;                       // nq: configuration tried by the line search
  VectorX rhs;                         // m
  VectorX predicted;                   // nv: h v + h^2/2 a
  /// Whether data holds M's factor of a solved point (the Newton iterations' metric).
  bool metric_held = false;
  /// The rank of J at the first point: the reference for singular configurations.
  int reference_rank = -1;
};

/// What the position solve at one time point did.
struct KinematicPoint {
  bool converged = false;
  int newton_iterations = 0;
  double equation_residual = 0.0;  // max |Phi| at the solution [m or rad]
  double last_step = 0.0;          // max |dq| of the last Newton step [m or rad]
  /// sigma_rank / sigma_max of the weighted constraint Jacobian at the solution (rank:
  /// the reference rank); 1 without constraints.
  double singular_ratio = 1.0;
  int rank = 0;  // rank of J at the solution
};

/// Newton iterations on Phi(q, t) = 0 from the guess in q [s]. Leaves the position stage,
/// J (data.constraint_jacobian) and its factorization at the returned q.
KinematicPoint solve_positions(const Model& model, Data& data, KinematicWorkspace& workspace,
                               const KinematicSettings& settings, double t, VectorX& q);

/// v (nv) = the minimum-norm solution of J v = nu(t), then a (nv) of J a = gamma(t, q, v),
/// on the factorization solve_positions left; leaves the velocity stage at (q, v).
void solve_velocities_and_accelerations(const Model& model, Data& data, KinematicWorkspace& workspace, double t,
                                        const VectorX& q, VectorX& v, VectorX& a);

/// One time point: predicts q from the previous point (q, v, a at t - h; h = 0: q is the
/// first guess) by q + h v + h^2/2 a, solves positions, velocities and accelerations.
/// On failure (not converged) q holds the last iterate and v, a are unchanged.
KinematicPoint analyse_time_point(const Model& model, Data& data, KinematicWorkspace& workspace,
                                  const KinematicSettings& settings, double t, double h, VectorX& q, VectorX& v,
                                  VectorX& a);

/// A constraint row that depends on others in J but whose residual disagrees with
/// theirs: J_dependent = sum c_i J_i, yet Phi_dependent != sum c_i Phi_i. No q satisfies
/// both (an over-driven mechanism: two drivers on one coordinate with different motions,
/// or a driver on a coordinate the loops already fix).
struct InconsistentRows {
  int dependent = -1;     // the row found dependent (the pivoted QR's choice)
  std::vector<int> rows;  // the independent rows it combines (|c_i| > 1e-8 max |c|)
  double mismatch = 0.0;  // Phi_dependent - sum c_i Phi_i [m or rad]
};
/// The dependent rows of J at the current position stage whose residual (in
/// data.constraint_residual) is inconsistent beyond `tolerance` [m or rad]. For error
/// reports: allocates.
std::vector<InconsistentRows> inconsistent_rows(const Model& model, Data& data, double t, double tolerance);

}  // namespace heavesim
