// Forward dynamics: the two independent algorithms (ABA, and CRBA + Cholesky with the
// bias from RNEA) agree on random trees, the dispatcher returns what each returns,
// and a non-finite acceleration stops the system with a diagnosis.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/oscillators.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(ForwardDynamics, ArticulatedBodyAndCompositeRigidBodyAgree) {
  std::mt19937_64 random(51);
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomTreeAndState drawn = samples::random_tree_and_state(random, 14, trial % 2 == 0);
    const Model& model = drawn.model;
    const samples::RandomState& state = drawn.state;
    Data data(model);
    update_positions(model, data, state.q);
    update_velocities(model, data, state.q, state.v);
    const VectorX by_aba = forward_dynamics(model, data, state.tau, state.external_forces,
                                            ForwardDynamicsMethod::articulated_body);
    const VectorX by_crba = forward_dynamics(model, data, state.tau, state.external_forces,
                                             ForwardDynamicsMethod::composite_rigid_body);
    // Both solve M qdd = tau - C; their difference is bounded by cond(M) eps |qdd|.
    // cond(M) of these trees is below 1e4: bound 1e-10 (1 + |qdd|).
    EXPECT_LT((by_aba - by_crba).norm(), 1e-10 * (1.0 + by_aba.norm())) << "trial " << trial;
    EXPECT_EQ(by_aba, articulated_body_forward_dynamics(model, data, state.tau, state.external_forces));
    EXPECT_EQ(by_crba, composite_rigid_body_forward_dynamics(model, data, state.tau, state.external_forces));
  }
}

TEST(Dynamics, NonFiniteAccelerationStopsWithADiagnosisNamingTheJoint) {
  auto model = std::make_shared<const Model>(samples::prismatic_oscillator(1.0, 1e300));
  MultibodySystem system(model);
  VectorX y = system.initial_state(VectorX::Constant(1, 1e300), VectorX::Zero(1)), ydot(2);
  try {
    system.state_derivative(0.0, y, ydot);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("joint 'slide'"), std::string::npos) << error.what();
    EXPECT_FALSE(error.suggestion().empty());
  }
}

}  // namespace
}  // namespace heavesim
