#pragma once
// Velocity-level time stepping with unilateral contact, Coulomb friction and joint stops
// (Stewart & Trinkle 1996; Anitescu & Potra 1997), the scheme of Bullet's MLCP solver,
// ODE's dWorldStep and Erleben's Physics-Based Animation notes. One step of h:
//
//   v*  = v + h M^-1 (tau - C(q, v) + generalized gravity and external loads)
//   v+  = v* + M^-1 J^T z                  (z: impulses, N s or N m s)
//   w   = J v+ + b = A z + (J v* + b),   A = J M^-1 J^T (+ eps I)
//   normal and stop rows: 0 <= z  complementary to  w >= 0
//   friction rows t1, t2: |z_t| <= mu z_n, and w_t = 0 unless z_t is at its bound
//   q+  = q (+) h v+                       (on the configuration manifold; a free joint's
//                                           position along its parent-axes velocity)
//
// b holds the gap: b = gap / h lets a gap close exactly within the step but never pulls;
// an overlap is removed by the fraction `stabilization` per step; an impact faster than
// `restitution_threshold` leaves with e times its approach speed (Newton's law at the
// velocity level). Friction acts along k tangents per point, each boxed by
// |z_d| <= mu tan(pi/2k) z_n: the k boxes add up to the regular 2k-gon around the
// Coulomb circle (k = 2: the four-facet pyramid of ODE's dContactApprox1 and Bullet's
// limitDependency), a boxed MLCP that the Dantzig solver takes (kernel/complementarity).
// A point sliding at the step's start has one friction row instead, along its slip,
// boxed by mu z_n: Coulomb's sliding friction in any direction. Tension lines (hoist lines, ropes) are
// one-sided rows on the distance between two points. The derivation, the choices and
// their limits: docs/physics/contact.md.
//
// The model's own constraints (loop joints, couplers, drivers: a deck moved by a
// prescribed motion) enter as free rows, J_c v+ = -Phi(q, t + h) / h. Every buffer is
// sized at construction for `max_contacts` points, so a step does not allocate.
#include <span>
#include <utility>
#include <vector>

#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/complementarity/fallback_chain.hpp"
#include "kernel/contact/contact_detection.hpp"

namespace heavesim {

struct ContactStepOptions {
  double stabilization = 0.2;          ///< fraction of an overlap removed per step (ODE's ERP), in [0, 1]
  double restitution_threshold = 0.05; ///< m/s (rad/s for stops): slower impacts do not bounce
  /// eps = regularization x mean(diag A) added to A's diagonal (constraint-force
  /// mixing): with four points under a box face or a stack, J has dependent rows and A
  /// is singular; eps makes it positive definite at the cost of a contact velocity of
  /// eps z (1e-12 of the impulse scale; docs/physics/contact.md).
  double regularization = 1e-10;
  /// m/s: a point slipping faster than this at the step's start has one friction row,
  /// along its slip (mu z_n against the slip: Coulomb's sliding friction); slower points
  /// stick or start to slip within the pair's friction polygon.
  double sliding_speed_threshold = 1e-6;
  /// Dantzig first (exact, fast on the positive definite A), then projected Gauss-Seidel
  /// (warm-started from the last step's impulses when the contact set is unchanged),
  /// then Lemke (frictionless problems only).
  FallbackChainOptions solvers = default_solvers();
  static FallbackChainOptions default_solvers();
};

struct ContactStepReport {
  ComplementarityResult solve;  ///< status, the solver that ran, its residual (solve.attempts > 1: a fallback)
  int constraint_rows = 0;      ///< the model's constraint rows (free rows, first)
  int contacts = 0;             ///< contact points in the problem
  int active_stops = 0;         ///< joint-stop rows in the problem
  int taut_lines = 0;           ///< tension-line rows in the problem
  int rows = 0;                 ///< size of the complementarity problem
  bool ok() const { return solve.solved(); }  ///< a step without rows counts as solved
};

class ContactStepper {
 public:
  /// Throws ParameterError if check_contact_model fails or the options are out of range.
  ContactStepper(const Model& model, ContactModel contacts, int max_contacts, ContactStepOptions options = {});

  /// Advances (q, v) from time t [s] by one step of h [s, > 0] under the joint
  /// forces `tau` (nv) and the external wrenches per link (world, about the origin). On a
  /// solver failure (report.ok() false) q and v are left as they were.
  ContactStepReport step(Data& data, double t, double h, VectorX& q, VectorX& v, const VectorX& tau,
                         ExternalForces external = {});

  const ContactModel& contact_model() const { return contacts_; }
  const ContactStepOptions& options() const { return options_; }
  /// The contact points of the last step, and the impulse [N s, world] each applied to
  /// its pair's geometry a (b received the opposite).
  std::span<const ContactPoint> contacts() const { return {points_.data(), static_cast<size_t>(contact_count_)}; }
  Vector3 contact_impulse_world(int k) const;
  /// The torsional friction's angular impulse of point k [N m s] about its normal, on the
  /// pair's geometry a (b received the opposite); 0 without torsional friction.
  double contact_spin_impulse(int k) const;
  /// The impulse of joint stop s in the last step [N s or N m s], > 0 away from the bound
  /// reached (0 if the stop was not touched).
  double stop_impulse(int s) const;
  /// +1 if stop s acted at its lower bound in the last step (pushing the coordinate up),
  /// -1 at its upper bound, 0 if it was not in the problem.
  double stop_direction(int s) const { return stop_sign_[s]; }
  /// The impulse of tension line l in the last step [N s, >= 0; 0 if it was slack], and
  /// its ends and unit direction from end a to end b (world) at the step's start.
  double line_impulse(int l) const { return line_row_[l] < 0 ? 0.0 : impulses_[line_row_[l]]; }
  const Vector3& line_point_a_world(int l) const { return line_point_a_[l]; }
  const Vector3& line_point_b_world(int l) const { return line_point_b_[l]; }
  const Vector3& line_direction_world(int l) const { return line_direction_[l]; }

  /// Tangent d of k (the friction rows of a point): evenly spaced over half a turn from
  /// the point's tangent1 (odd k > 1: from tangent2), so that tangent1 is a face normal of
  /// the friction polygon; k = 1 (a sliding point): tangent1, its slip direction.
  static Vector3 friction_direction(const ContactPoint& point, int d, int k);
  /// mu's factor on each direction's box, tan(pi / 2k): the polygon's faces touch the
  /// circle of radius mu z_n (k = 1: 1).
  static double friction_box_scale(int k);

 private:
  void add_point_row(int row, int link, const Vector3& point, const Vector3& direction, double sign, const Data& data);
  /// Row `row` of J gains sign * axis . omega_link: the link's rotation rate about `axis`.
  void add_spin_row(int row, int link, const Vector3& axis, double sign, const Data& data);
  /// The rows of `report` built: A = J M^-1 J^T, the solve, v+ and q+ (step's second half).
  ContactStepReport solve_and_advance(ContactStepReport report, double h, VectorX& q, VectorX& v);
  /// Per point its friction rows: 0 without friction, 1 along its slip if it slips (its
  /// tangent1 turned into the slip direction), else the pair's friction_directions.
  void classify_friction(const Data& data);
  /// The chain failed on a problem with friction rows: the fixed point of Dantzig solves
  /// with the friction boxes held at the last normal impulses (z holds the start).
  ComplementarityResult solve_with_fixed_friction_bounds(const ComplementarityProblem& problem, VectorView z,
                                                         const ComplementarityResult& chain);
  /// Calls visit(c) once for every column c of J that row `row` can have nonzero.
  template <typename Visit>
  void for_each_row_column(int row, Visit&& visit) const;

  const Model& model_;
  ContactModel contacts_;
  ContactStepOptions options_;
  int capacity_rows_ = 0;
  std::vector<int> free_joints_;        ///< joints of type free (stepped in their parent's axes)
  std::vector<ContactPoint> points_;
  int contact_count_ = 0;
  std::vector<int> contact_first_row_;  ///< per point: its normal row (its friction rows follow)
  std::vector<int> friction_rows_;      ///< per point: friction rows (classify_friction)
  std::vector<int> spin_rows_;          ///< per point: 1 with torsional friction, else 0
  std::vector<int> stop_row_;           ///< per stop: its row, -1 if not in the problem
  std::vector<double> stop_sign_;       ///< per stop: +1 lower bound reached, -1 upper
  std::vector<int> line_row_;           ///< per line: its row, -1 if slack beyond the margin
  std::vector<Vector3> line_point_a_, line_point_b_, line_direction_;  ///< per line, world
  int previous_rows_ = -1;
  VectorX zero_acceleration_, free_velocity_, velocity_next_;
  VectorX configuration_next_;
  MatrixX mass_factor_;      ///< nv x nv: L of M = L^T L (ancestor entries only)
  MatrixX jacobian_;         ///< rows x nv
  std::vector<std::pair<int, int>> row_links_;  ///< per row: the two links whose chains it touches
  MatrixX minv_jacobian_t_;  ///< nv x rows: M^-1 J^T
  MatrixX delassus_;         ///< rows x rows: A
  VectorX offset_, impulses_, previous_impulses_, friction_coefficient_, lower_, upper_;
  VectorX fixed_lower_, fixed_upper_, previous_normal_, best_impulses_;  ///< solve_with_fixed_friction_bounds
  Eigen::VectorXi friction_normal_;
  ComplementarityWorkspace workspace_;
  bool chain_has_dantzig_ = false;  ///< the fixed-friction-box fallback solves with Dantzig: only if the chain allows it
};

}  // namespace heavesim
