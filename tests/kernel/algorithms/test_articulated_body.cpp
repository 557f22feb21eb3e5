// The articulated-body algorithm against inverse dynamics on random trees with every
// joint type, added inertia and external forces: RNEA(q, v, ABA(q, v, tau)) = tau.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(ArticulatedBody, InverseDynamicsOfItsAccelerationsReturnsTheForces) {
  std::mt19937_64 random(41);
  for (int trial = 0; trial < 10; ++trial) {
    samples::RandomTreeOptions options;
    options.bodies = 15;
    options.added_inertia = trial % 2 == 1;
    options.chain = trial % 3 == 0;
    const Model model = samples::random_tree(random, options);
    Data data(model);
    const samples::RandomState state = samples::random_state(model, random);
    const VectorX qdd = aba(model, data, state.q, state.v, state.tau, state.external_forces);
    const VectorX tau = rnea(model, data, state.q, state.v, qdd, state.external_forces);
    // ABA is backward stable: the residual is a few eps times the forces involved
    // (|tau| and the inertial forces |M qdd|, of order 10-100); bound 1e-11 relative.
    EXPECT_LT((tau - state.tau).norm(), 1e-11 * (1.0 + state.tau.norm() + qdd.norm())) << "trial " << trial;
  }
}

}  // namespace
}  // namespace heavesim
