// The O(n) generalized applied force Q = tau + sum_i J_i^T f_i against the O(n^2)
// Jacobian-transpose sum, with each link Jacobian column J_i e_k read off the velocity
// stage for the unit speed v = e_k (the velocity is linear in v).
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/generalized_force.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(GeneralizedAppliedForce, EqualsTheJacobianTransposeSum) {
  std::mt19937_64 random(21);
  for (int trial = 0; trial < 6; ++trial) {
    samples::RandomTreeOptions options;
    options.bodies = 8;
    const Model model = samples::random_tree(random, options);
    Data data(model);
    const samples::RandomState state = samples::random_state(model, random);
    update_positions(model, data, state.q);

    AlignedVector<Force> subtree_forces(model.num_links(), Force::Zero());
    VectorX generalized_force(model.nv);
    generalized_applied_force(model, data, state.external_forces, state.tau, subtree_forces, generalized_force);

    VectorX expected = state.tau;
    Data unit_speed(model);
    update_positions(model, unit_speed, state.q);
    for (int k = 0; k < model.nv; ++k) {
      update_velocities(model, unit_speed, state.q, VectorX::Unit(model.nv, k));
      for (int i = 1; i < model.num_links(); ++i) expected[k] += dot(unit_speed.velocity_world[i], state.external_forces[i]);
    }
    EXPECT_LT((generalized_force - expected).norm(), 1e-12 * (1.0 + expected.norm())) << "trial " << trial;
  }
}

}  // namespace
}  // namespace heavesim
