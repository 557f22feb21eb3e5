// Joint reactions against statics: a hanging chain at rest carries the weight below
// each joint.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "samples/hanging_chain.hpp"

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

}  // namespace
}  // namespace heavesim
