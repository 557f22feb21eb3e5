// Joint reactions against statics and Newton's second law: a hanging chain at rest
// carries the weight below each joint; a swinging pendulum's pin pushes with
// m (a_com - g) and, being a passive hinge, transmits no moment about its pin; the
// articulated-body pass's wrenches (f = I^A a + p^A) against the inverse-dynamics pass's on
// random trees, and when they may not be used.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "samples/hanging_chain.hpp"
#include "samples/planar_chains.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(Dynamics, HangingChainAtRestCarriesTheWeightBelowEachJoint) {
  const double masses[3] = {2.0, 3.0, 5.0};
  const Model model = samples::hanging_chain({masses[0], masses[1], masses[2]});
  Data data(model);
  const VectorX q = model.neutral_configuration(), v = VectorX::Zero(model.nv);
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  const VectorX qdd = articulated_body_forward_dynamics(model, data, VectorX::Zero(model.nv));
  EXPECT_LT(qdd.norm(), 1e-14);
  compute_joint_wrenches(model, data);
  for (int i = 0; i < 3; ++i) {
    double weight_below = 0.0;
    for (int j = i; j < 3; ++j) weight_below += masses[j] * 9.81;
    const JointReaction reaction = joint_reaction(model, data, i + 1);
    EXPECT_NEAR(reaction.force_world.z(), weight_below, 1e-12 * weight_below);
    EXPECT_NEAR(reaction.force_world.head<2>().norm(), 0.0, 1e-12);
    EXPECT_NEAR(reaction.moment_world.norm(), 0.0, 1e-12);  // every CoM is straight below its joint
  }
}

TEST(JointReactions, SwingingPendulumPinForceIsMassTimesCentreOfMassAccelerationMinusGravity) {
  const double mass = 2.0, com = 0.6, inertia = 0.24, g = 9.81;
  const Model model = samples::pendulum(mass, com, inertia);
  Data data(model);
  const double angle = 0.7, rate = -1.3;
  update_positions(model, data, VectorX::Constant(1, angle));
  update_velocities(model, data, VectorX::Constant(1, angle), VectorX::Constant(1, rate));
  const double acceleration = articulated_body_forward_dynamics(model, data, VectorX::Zero(1))[0];
  compute_joint_wrenches(model, data);
  const JointReaction reaction = joint_reaction(model, data, 1);

  // Free swing: qdd = -m g a sin(q) / (I_c + m a^2). The CoM is at
  // p = -a (sin q, 0, cos q), so p'' = -a qdd (cos q, 0, -sin q) + a q'^2 (sin q, 0, cos q);
  // the pin force F = m p'' - m g with g = (0, 0, -9.81).
  const double expected_acceleration = -mass * g * com * std::sin(angle) / (inertia + mass * com * com);
  EXPECT_NEAR(acceleration, expected_acceleration, 1e-14);
  const Vector3 com_acceleration = -com * acceleration * Vector3(std::cos(angle), 0.0, -std::sin(angle)) +
                                   com * rate * rate * Vector3(std::sin(angle), 0.0, std::cos(angle));
  const Vector3 expected_force = mass * com_acceleration + mass * g * Vector3::UnitZ();
  // Forces of order 20 N: round-off ~1e-14 N, bound 1e-12 N.
  EXPECT_LT((reaction.force_world - expected_force).norm(), 1e-12);
  // Moments about the pin: the weight's and the inertial moments balance about +Y (no
  // applied torque) and the rod's symmetric inertia leaves nothing about X or Z.
  EXPECT_LT(reaction.moment_world.norm(), 1e-12);
}

TEST(JointReactions, TheArticulatedBodyPassesWrenchesAreTheInverseDynamicsPasses) {
  // Two algorithms for the same wrenches: f_i = I^A_i a_i + p^A_i from the articulated-body
  // pass just made, and the inverse-dynamics pass at its accelerations (compute_joint_wrenches),
  // on random trees with every joint type (free joints among them), added inertia, joint
  // forces and external forces on every link.
  std::mt19937_64 random(73);
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomTreeAndState drawn = samples::random_tree_and_state(random, 15, trial % 2 == 1, trial % 3 == 0);
    const Model& model = drawn.model;
    const samples::RandomState& state = drawn.state;
    Data data(model);
    update_positions(model, data, state.q);
    update_velocities(model, data, state.q, state.v);
    articulated_body_forward_dynamics(model, data, state.tau, state.external_forces);
    ASSERT_TRUE(articulated_body_joint_wrenches(model, data)) << "trial " << trial;
    EXPECT_TRUE(data.stages.current & StageMarker::reactions);
    const AlignedVector<Force> from_articulated = data.joint_wrench_world;
    compute_joint_wrenches(model, data, state.external_forces);
    double scale = 1.0;  // the largest wrench: a joint near the root carries forces of order 100
    for (int i = 1; i < model.num_links(); ++i) scale = std::max(scale, data.joint_wrench_world[i].vector().norm());
    for (int i = 1; i < model.num_links(); ++i)
      EXPECT_LT((from_articulated[i].vector() - data.joint_wrench_world[i].vector()).norm(), 1e-12 * scale)
          << "trial " << trial << " joint " << i;
    // The inverse-dynamics pass overwrote the accelerations: the articulated-body wrenches
    // are no longer the evaluation's.
    EXPECT_FALSE(articulated_body_joint_wrenches(model, data));
    // A new evaluation whose acceleration stage some other pass marked current: the
    // articulated-body pass was another evaluation's (its number, not the stage bit, tells).
    articulated_body_forward_dynamics(model, data, state.tau, state.external_forces);
    data.stages.same_state_again();
    data.stages.accelerations_computed();
    EXPECT_FALSE(articulated_body_joint_wrenches(model, data));
  }
}

}  // namespace
}  // namespace heavesim
