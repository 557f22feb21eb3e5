// K6: algorithms cross-checked against each other on random trees with every joint
// type, joint springs and external forces:
//   * CRBA mass matrix vs RNEA columns M e_j = RNEA(q, 0, e_j) - RNEA(q, 0, 0);
//   * ABA vs CRBA + Cholesky forward dynamics (also with added inertia);
//   * joint reactions vs a body-by-body classical Newton-Euler sum over each subtree,
//     sum_j (m_j a_cj - m_j g - f_j) and the matching moment about the joint origin.
#include <random>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "samples/random_models.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {
namespace {

/// Subtree wrench [moment about p; force] from each body's CoM motion, world axes.
Vector6 subtree_wrench(const Model& model, const Data& data, const AlignedVector<Force>& external, int root,
                       const Vector3& p) {
  Vector3 force = Vector3::Zero(), moment = Vector3::Zero();
  for (int j = root; j < model.links[root].subtree_end; ++j) {
    const Inertia& inertia = model.links[j].inertia;
    const Matrix3& R = data.X_world_link[j].rotation();
    const Vector3 c = data.X_world_link[j].act_point(inertia.com());
    const Vector3 omega = data.velocity_world[j].angular(), alpha = data.acceleration_world[j].angular();
    // Classical CoM acceleration from the spatial (world-origin) velocity and acceleration.
    const Vector3 v_c = data.velocity_world[j].linear() + omega.cross(c);
    const Vector3 a_c = data.acceleration_world[j].linear() + alpha.cross(c) + omega.cross(v_c);
    const Matrix3 I_c = R * inertia.inertia_com() * R.transpose();
    const Vector3 applied = inertia.mass() * model.gravity + external[j].linear();
    force += inertia.mass() * a_c - applied;
    moment += (c - p).cross(inertia.mass() * a_c) + I_c * alpha + omega.cross(I_c * omega);
    moment -= (c - p).cross(inertia.mass() * model.gravity) + external[j].moment_about(p);
  }
  Vector6 wrench;
  wrench << moment, force;
  return wrench;
}

}  // namespace

std::vector<ValidationRow> check_k6_algorithm_cross_checks() {
  double crba_error = 0.0, aba_error = 0.0, aba_added_error = 0.0, reaction_error = 0.0;
  std::mt19937_64 random(6);
  for (int trial = 0; trial < 50; ++trial) {
    for (bool added : {false, true}) {
      samples::RandomTreeOptions options;
      options.bodies = 14;
      options.added_inertia = added;
      const Model model = samples::random_tree(random, options);
      Data data(model);
      samples::RandomState state = samples::random_state(model, random);
      add_joint_element_forces(model, state.q, state.v, state.tau);

      // CRBA vs RNEA columns.
      const VectorX zero = VectorX::Zero(model.nv);
      const MatrixX M = crba(model, data, state.q);
      const VectorX gravity_only = rnea(model, data, state.q, zero, zero);
      MatrixX columns(model.nv, model.nv);
      for (int j = 0; j < model.nv; ++j)
        columns.col(j) = rnea(model, data, state.q, zero, VectorX::Unit(model.nv, j)) - gravity_only;
      crba_error = std::max(crba_error, (M - columns).norm() / M.norm());

      // ABA vs CRBA + Cholesky.
      update_positions(model, data, state.q);
      update_velocities(model, data, state.q, state.v);
      const VectorX qdd_crba = composite_rigid_body_forward_dynamics(model, data, state.tau, state.external_forces);
      const VectorX qdd_aba = articulated_body_forward_dynamics(model, data, state.tau, state.external_forces);
      (added ? aba_added_error : aba_error) =
          std::max(added ? aba_added_error : aba_error, (qdd_aba - qdd_crba).norm() / qdd_crba.norm());
      if (added) continue;

      // Reactions vs subtree Newton-Euler.
      compute_joint_wrenches(model, data, state.external_forces);
      for (int i = 1; i < model.num_links(); ++i) {
        const JointReaction reaction = joint_reaction(model, data, i);
        const Vector6 expected = subtree_wrench(model, data, state.external_forces, i, data.X_world_link[i].translation());
        Vector6 kernel;
        kernel << reaction.moment_world, reaction.force_world;
        reaction_error = std::max(reaction_error, (kernel - expected).norm() / expected.norm());
      }
    }
  }
  const std::string subject = "50 random 14-body trees, all 7 joint types";
  return {{"K6", subject, "CRBA vs RNEA columns, relative", crba_error, 1e-12},
          {"K6", subject, "ABA vs CRBA + Cholesky, relative", aba_error, 1e-12},
          {"K6", subject + " + added inertia", "ABA vs CRBA + Cholesky, relative", aba_added_error, 1e-12},
          {"K6", subject, "reactions vs subtree Newton-Euler, relative", reaction_error, 1e-12}};
}

}  // namespace heavesim::validation
