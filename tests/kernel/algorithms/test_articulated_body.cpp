// The articulated-body algorithm against inverse dynamics on random trees with every
// joint type, added inertia and external forces: RNEA(q, v, ABA(q, v, tau)) = tau; and
// against the mass matrix on a floating base that carries limbs (ABA solves for the base's
// qdd in its backward pass): M(q) qdd = tau - RNEA(q, v, 0).
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "samples/bench_models.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(ArticulatedBody, InverseDynamicsOfItsAccelerationsReturnsTheForces) {
  std::mt19937_64 random(41);
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomTreeAndState drawn = samples::random_tree_and_state(random, 15, trial % 2 == 1, trial % 3 == 0);
    const Model& model = drawn.model;
    const samples::RandomState& state = drawn.state;
    Data data(model);
    const VectorX qdd = aba(model, data, state.q, state.v, state.tau, state.external_forces);
    const VectorX tau = rnea(model, data, state.q, state.v, qdd, state.external_forces);
    // ABA is backward stable: the residual is a few eps times the forces involved
    // (|tau| and the inertial forces |M qdd|, of order 10-100); bound 1e-11 relative.
    EXPECT_LT((tau - state.tau).norm(), 1e-11 * (1.0 + state.tau.norm() + qdd.norm())) << "trial " << trial;
  }
}

TEST(ArticulatedBody, AFloatingBaseWithLimbsAgreesWithTheMassMatrix) {
  // The humanoid: a free torso (the world its parent) with two legs and two arms.
  const Model model = samples::to_model(samples::humanoid32());
  ASSERT_EQ(model.joints[1].nv, 6);
  ASSERT_EQ(model.joints[1].parent, 0);
  Data data(model);
  const samples::BenchStates states = samples::bench_states(model, 5, 17);
  for (std::size_t k = 0; k < states.q.size(); ++k) {
    const VectorX qdd = aba(model, data, states.q[k], states.v[k], states.tau[k]);
    const VectorX bias = rnea(model, data, states.q[k], states.v[k], VectorX::Zero(model.nv));
    update_positions(model, data, states.q[k]);
    const MatrixX M = mass_matrix(model, data);
    const VectorX expected = M.llt().solve(states.tau[k] - bias);
    EXPECT_LT((qdd - expected).norm(), 1e-10 * (1.0 + expected.norm())) << "state " << k;
    EXPECT_GT(qdd.head<6>().norm(), 1e-3);  // the base moves: its qdd is not trivially zero
  }
}

}  // namespace
}  // namespace heavesim
