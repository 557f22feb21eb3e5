#pragma once
// Workspace of the algorithms for one Model (Pinocchio's Data): every buffer is sized
// once, so no algorithm allocates after its first call. One Model can serve many Data.
// The O(n) buffers are sized here; the dense nv x nv matrices (mass_matrix and its
// factor, dtau_dq, dtau_dv) by the first call of the algorithm that fills them
// (size_dense_matrix): a case that never forms them does not pay n^2 memory and time
// for them, and making a Data is O(n) (docs/performance.md, "Set-up").
//
// All spatial quantities are in world coordinates about the world origin
// ("absolute" spatial vectors, Featherstone 2008 sec. 2.8 / Pinocchio's WORLD
// convention): composite and articulated inertias then add without transforms.
#include <limits>

#include "kernel/math/regularized_symmetric_solver.hpp"
#include "kernel/math/sized_cholesky.hpp"
#include "kernel/model/model.hpp"

namespace heavesim {

using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

/// Which stages of a Data hold values of one evaluation (MuJoCo's computed-stage
/// flags, Simbody's realization stages). Every algorithm that computes a stage says so,
/// and a stage invalidates the ones that derive from it: new positions start a new
/// evaluation (nothing else is current); new velocities on the same positions are a new
/// evaluation too (the old accelerations and wrenches are gone); new accelerations
/// leave the reactions of the old ones behind. The system that evaluates at a time t
/// records t. A reader keeps the evaluation number and asks require_stages().
/// mass_factor marks a position-level product: M(q) and its Cholesky factor at this
/// evaluation's positions (factorize_mass_matrix), kept while only speeds or
/// accelerations change, so that the solves of one configuration factorize M once.
struct StageMarker {
  enum Stage : unsigned { positions = 1u, velocities = 2u, accelerations = 4u, reactions = 8u, mass_factor = 16u };
  unsigned current = 0;  // bits of the stages computed in this evaluation
  /// Renewed by every position or velocity stage, and unique in the process (0: no stage
  /// yet): two Data hold the same number only when one is a copy of the other's
  /// evaluation, so an element may key what it computed from one evaluation on this
  /// number, whichever Data it is handed next (kernel/elements/evaluation_key.hpp).
  long evaluation = 0;
  double time = std::numeric_limits<double>::quiet_NaN();  // s, of this evaluation (NaN: not recorded)

  /// A number no StageMarker of this process has held: each thread takes them from a
  /// range of its own (no shared counter touched per evaluation).
  static long fresh_evaluation_number();

  void begin_evaluation() {
    current = positions;
    evaluation = fresh_evaluation_number();
    time = std::numeric_limits<double>::quiet_NaN();
  }
  void velocities_computed() {
    current = (current & (positions | mass_factor)) | velocities;
    evaluation = fresh_evaluation_number();
    time = std::numeric_limits<double>::quiet_NaN();
  }
  void accelerations_computed() { current = (current & (positions | velocities | mass_factor)) | accelerations; }
  void reactions_computed() { current |= reactions; }
  /// An inverse-dynamics pass for an acceleration of the caller's overwrote the
  /// acceleration stage and the joint wrenches.
  void accelerations_overwritten() { current &= positions | velocities | mass_factor; }
  /// The positions and speeds asked for are those already held: a new evaluation whose
  /// position and velocity stages (and M's factor) stand; nothing derived from forces does.
  void same_state_again() {
    current &= positions | velocities | mass_factor;
    evaluation = fresh_evaluation_number();
    time = std::numeric_limits<double>::quiet_NaN();
  }
};

struct Data {
  explicit Data(const Model& model);

  StageMarker stages;  // what below is current, and for which evaluation

  // --- position stage (update_positions) ---
  // The joint coordinates of this stage (nq), kept as MuJoCo's mjData keeps qpos: the
  // expression constraints' Jacobian row df/dx reads them, so that constraint_jacobian
  // and its many callers need not pass q beside the Data computed from it.
  VectorX q;
  // cos q and sin q of the revolute joints' coordinates (Model::revolute_coordinates), at
  // those coordinates' indices (nq each; the other entries are unused).
  VectorX revolute_cos, revolute_sin;
  AlignedVector<Transform> X_world_link;    // link frame in the world
  Matrix6X motion_subspace_world;           // 6 x nv: column k = spatial motion per unit v_k
  AlignedVector<Inertia> rigid_inertia_world;  // rigid-body inertia of each link
  AlignedVector<Matrix6> added_inertia_world;  // added inertia (e.g. hydrodynamic), links that have one

  // --- velocity stage (update_velocities) ---
  VectorX v;  // nv: the joint velocities of this stage (mjData's qvel), for constraint_bias
  AlignedVector<Motion> velocity_world;           // spatial velocity v_i of each link
  AlignedVector<Motion> bias_acceleration_world;  // c_i = dS_i/dt v_i (velocity-product term)
  AlignedVector<Force> momentum_world;            // h_i = I_i v_i, rigid plus added inertia [N s, N m s]
  AlignedVector<Force> bias_force_world;          // v_i x* h_i

  // --- acceleration stage ---
  VectorX qdd;                                    // nv, joint accelerations
  AlignedVector<Motion> acceleration_world;       // spatial acceleration a_i of each link
  AlignedVector<Force> joint_wrench_world;        // f_i: total wrench of parent on child through joint i
  VectorX tau;                                    // nv, generalized forces from inverse dynamics

  // --- mass matrix (CRBA) ---
  // Composite inertia of each link's subtree, world coordinates about the origin: the
  // rigid bodies' part, and the added (e.g. hydrodynamic) part of the subtrees that have
  // any (composite_has_added_inertia; the others skip it: cost follows the case).
  AlignedVector<InertiaAboutOrigin> composite_rigid_inertia_world;
  AlignedVector<Matrix6> composite_added_inertia_world;
  std::vector<unsigned char> composite_has_added_inertia;
  MatrixX mass_matrix;                            // nv x nv, both triangles filled; 0 x 0 until the first CRBA
  SizedCholesky mass_matrix_cholesky;           // of mass_matrix; current with StageMarker::mass_factor;
                                                // sized by the first factorize_mass_matrix

  // --- constraints (closed loops); sized m = model.num_constraint_rows ---
  VectorX constraint_residual;      // Phi (m)
  VectorX constraint_velocity_target;  // nu = -dPhi/dt (m): J v = nu; nonzero only for drivers
  MatrixX constraint_jacobian;      // J (m x nv)
  VectorX constraint_bias;          // gamma = -dJ/dt v (m)
  VectorX constraint_multipliers;   // lambda (m): M qdd + C = tau + J^T lambda
  // Rows the KKT solve uses (1) or sets aside as redundant (0). The explicit methods
  // choose them after every step on a mechanism with redundant rows (ode_form.cpp); by
  // default every row is used and constraint_rows_set_aside is false.
  VectorX constraint_row_used;      // m
  bool constraint_rows_set_aside = false;
  // Whether each row holds now (1) or not (0): a joint stop's row only while the stop is
  // active (joint_stop_events.hpp); every other row always. An inactive row is zero in
  // Phi, J, nu and gamma, and takes no part in a form's rows.
  VectorX constraint_active;        // m
  MatrixX kkt_minv_jt;              // M^-1 J^T (nv x m)
  MatrixX kkt_schur;                // J M^-1 J^T (m x m)
  VectorX kkt_rhs;                  // m
  VectorX kkt_free_qdd;             // nv: qdd without constraint forces
  RegularizedSymmetricSolver kkt_solver;  // (J M^-1 J^T + epsilon I)^-1
  VectorX projection_step;          // nv: Newton correction in velocity coordinates
  VectorX projection_configuration; // nq

  // --- derivatives of inverse dynamics ---
  MatrixX dtau_dq;                                // nv x nv: d tau / d q along each joint's tangent
  MatrixX dtau_dv;                                // nv x nv: d tau / d v (both 0 x 0 until the first call)
  AlignedVector<Motion> derivative_velocity;      // workspace: d v_k for the current column
  AlignedVector<Motion> derivative_acceleration;  // workspace: d a_k
  AlignedVector<Force> derivative_force;          // workspace: d f_k, then subtree sums d F_k

  // --- articulated-body workspace (ABA) ---
  AlignedVector<Matrix6> articulated_inertia_world;
  AlignedVector<Force> articulated_bias_world;
  Matrix6X aba_U;                                 // 6 x nv: U_i = I^A_i S_i
  std::vector<SmallMatrix> aba_D_inverse;         // per link, nv_i x nv_i (not formed for a floating base: ABA solves for its qdd)
  VectorX aba_u;                                  // nv: u_i = tau_i - S_i^T p^A_i
  /// The evaluation (stages.evaluation) whose accelerations the last articulated-body pass
  /// computed, its I^A and p^A standing with them; 0 once an inverse-dynamics pass has
  /// overwritten the accelerations. articulated_body_joint_wrenches reads it.
  long articulated_evaluation = 0;
};

/// Throws std::logic_error (naming what is stale) unless every stage in `required` (bits
/// of StageMarker::Stage) is current in `data` for evaluation number `evaluation` at
/// time t [s]: a read of stages that a later evaluation overwrote, or that were never
/// computed. A few integer and double comparisons: cheap enough to stay on.
void require_stages(const Data& data, unsigned required, double t, long evaluation);

/// Gives a dense workspace its size, zeroed, on the algorithm's first call; afterwards a
/// size check only (no allocation: the hot path's rule holds from the second call on,
/// and every system form evaluates once before its first step).
inline void size_dense_matrix(MatrixX& matrix, Eigen::Index rows, Eigen::Index cols) {
  if (matrix.rows() != rows || matrix.cols() != cols) matrix.setZero(rows, cols);
}

}  // namespace heavesim
