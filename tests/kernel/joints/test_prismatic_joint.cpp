// The prismatic joint: a pure translation q along z (no rotation), S = [0; e_z]; a
// block on a vertical prismatic joint falls freely at -g and, with a spring, the
// joint force is -k q whatever the orientation of the rest of the model.
#include <gtest/gtest.h>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/joints/joint.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

TEST(PrismaticJoint, TransformIsAPureTranslationAlongZ) {
  const PrismaticJoint joint;
  for (const double stroke : {0.0, 0.25, -3.5}) {
    const Transform X = joint.transform(&stroke);
    EXPECT_EQ(X.rotation(), Matrix3::Identity());
    EXPECT_EQ(X.translation(), Vector3(0.0, 0.0, stroke));
    Vector6 axis;
    axis << 0, 0, 0, 0, 0, 1;
    EXPECT_EQ(Vector6(joint.motion_subspace(&stroke)), axis);
  }
}

TEST(PrismaticJoint, BlockFallsFreelyAlongItsAxisAndMovesWithoutTurning) {
  const Model model = samples::prismatic_oscillator(3.0, 0.0, std::nullopt, Vector3(0, 0, -9.81));
  Data data(model);
  const VectorX q = VectorX::Constant(1, 1.7), v = VectorX::Constant(1, -0.4);
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  // The block sits at (0, 0, q) with the world's orientation and moves at (0, 0, v).
  const Transform body = data.X_world_link[1] * model.links[1].X_link_body;
  EXPECT_LT((body.rotation() - Matrix3::Identity()).norm(), 1e-15);
  EXPECT_LT((body.translation() - Vector3(0, 0, 1.7)).norm(), 1e-15);
  EXPECT_LT(data.velocity_world[1].angular().norm(), 1e-15);
  EXPECT_LT((data.velocity_world[1].linear() - Vector3(0, 0, -0.4)).norm(), 1e-15);
  // Free fall: qdd = -g exactly up to round-off of one division (bound 1e-14).
  EXPECT_NEAR(articulated_body_forward_dynamics(model, data, VectorX::Zero(1))[0], -9.81, 1e-14);
}

}  // namespace
}  // namespace heavesim
