#pragma once
#include <optional>
// Hilber-Hughes-Taylor (HHT-alpha) integration of the index-3 equations of motion with
// an augmented Lagrangian and projections -- the structural-dynamics scheme that
// commercial multibody codes use for closed loops (ADAMS' HHT, Chrono's HHT; the
// "ALI3-P" formulation of Bayo & Ledesma 1996 and Cuadrado, Cardenal & Bayo 1997).
//
// Per step of size h, with gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4 and the
// unknown Delta = q_{n+1} "-" q_n (tangent coordinates, so quaternion joints move on
// the manifold, as in Bruls & Cardona's Lie-group Newmark):
//   Delta   = h v_n + h^2 [(1/2 - beta) a_n + beta a_{n+1}]
//   v_{n+1} = v_n + h [(1 - gamma) a_n + gamma a_{n+1}]
//   z_{n+1} = z_n + h [(1 - gamma) zdot_n + gamma zdot_{n+1}]   (element states)
//   M a_{n+1} + (1 + alpha) f_{n+1} - alpha f_n = 0,   f = C - Q - J^T lambda
//   lambda <- lambda - p Phi(q_{n+1})   at every Newton iteration (augmented Lagrangian)
// Newton's matrix (M + gamma h (1+alpha) dR/dv + beta h^2 (1+alpha) (dR/dq + p J^T J))
// is positive definite even where J loses rank, so singular configurations (the
// four-bars of IFToMM A02 lying flat) and redundant constraints pass without special
// treatment; Phi = 0 is met at position level, so the loop cannot drift. (It leaves out
// the constraint forces' geometric stiffness, see SecondOrderSystem::dynamics_derivatives.)
// The iteration converges when the speeds' remaining error is within rtol/atol (an
// error d in Delta is d gamma/(beta h) in v). After each
// step, velocities and accelerations are projected onto J v = nu and J a = gamma,
// mass-orthogonally: x -= M^-1 J^T (J M^-1 J^T + epsilon I)^-1 (J x - target), epsilon
// 1e-8 of the largest diagonal, which fades out redundant rows and rows being lost
// near a singular configuration (regularized_symmetric_solver.hpp).
//
// alpha in [-1/3, 0]: 0 is the trapezoidal rule (no numerical dissipation, second
// order); negative values damp frequencies above ~1/h (stiff elements, end stops).
// The step is fixed (IntegratorSettings::step); a step whose Newton iteration fails
// is retried in halves, down to 1/1024 of it, before the run stops with a diagnosis.
#include <string>
#include <vector>

#include "kernel/math/regularized_symmetric_solver.hpp"
#include "kernel/math/sized_cholesky.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/second_order_system.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace heavesim {

class HhtIntegrator : public Integrator {
 public:
  HhtIntegrator(SecondOrderSystem& system, const IntegratorSettings& settings);
  void initialize(double t0, const VectorX& y0) override;
  void advance_to(double t_out) override;
  const VectorX& state() const override { return y_; }
  double time() const override { return t_; }
  IntegratorStatistics statistics() const override { return statistics_; }

 private:
  /// One step of size h from (t_, y_); false if Newton's iteration did not converge.
  bool try_step(double h);
  /// The configuration, speeds and element states of the current Newton iterate.
  void iterate_state(double h);
  /// Newton's matrix and the penalty at the current iterate, for step size h.
  void build_newton_matrix(double h);
  /// Accepts the iterate as the state at t_ + h and projects v and a.
  void accept_step(double h);
  /// x -= M^-1 J^T (J M^-1 J^T)^+ (J x - target), with the factors of the last accept.
  void project(VectorX& x, const VectorX& target);
  [[noreturn]] void fail(double h);

  IntegratorSettings settings_;
  double alpha_, beta_, gamma_;
  SecondOrderSystem& system_;
  int nq_ = 0, nv_ = 0, nz_ = 0, m_ = 0;
  double t_ = 0.0;
  VectorX y_;                                  // [q; v; z] at t_
  VectorX acceleration_, rate_, multipliers_;  // a_n, zdot_n, lambda_n (of the applied force)
  VectorX final_constraint_residual_;          // Phi at the end of the last step
  VectorX previous_force_;                     // f_n = (C - Q - J^T lambda)_n (the HHT term), N or N m
  VectorX zero_acceleration_;
  IntegratorStatistics statistics_;
  // Newton iteration
  double penalty_ = 0.0;           // p [N/m or N m/rad]: c = beta h^2 (1 + alpha) p
  double matrix_step_ = 0.0;       // the h Newton's matrix was built for; 0 = none
  VectorX delta_, z_, a_, zdot_, lambda_, force_multipliers_, y_iterate_, q_start_, q_step_, residual_, correction_, phi_;
  DynamicsDerivatives derivatives_;
  MatrixX newton_matrix_;
  Eigen::PartialPivLU<MatrixX> newton_lu_;
  MatrixX active_jacobian_;  // the rows of J not identically zero, gathered for the penalty's J^T J
  // Projections
  ConstraintTerms terms_;
  SizedCholesky mass_llt_;
  std::vector<int> projection_rows_;           // rows independent at the start
  MatrixX projection_jacobian_;                // J of those rows
  MatrixX whitened_jacobian_t_;                // W = L^-1 J^T (those rows) with M = L L^T
  MatrixX schur_;                              // J M^-1 J^T = W^T W, lower triangle
  RegularizedSymmetricSolver schur_solver_;
  VectorX projection_residual_, projection_multipliers_, projection_step_, speeds_, gamma_target_;
  // Diagnosis of the last failed step
  double worst_residual_ = 0.0;
  std::optional<NumericalError> last_failure_;  // an evaluation's own error (non-finite, out of range)
  int worst_row_ = 0;
};

}  // namespace heavesim
