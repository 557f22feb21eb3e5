// The revolute joint against the rotation about z written out: X_J(q) = Rz(q), no
// translation, S = [e_z; 0]; and on a pendulum, the joint's world subspace is the
// user's axis (+Y) through the pin.
#include <gtest/gtest.h>

#include "kernel/algorithms/kinematics.hpp"
#include "kernel/joints/joint.hpp"
#include "samples/planar_chains.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

TEST(RevoluteJoint, TransformIsTheRotationAboutZ) {
  const RevoluteJoint joint;
  for (const double angle : {0.0, 0.4, -2.9, 7.0}) {
    const Transform X = joint.transform(&angle);
    // Entries of order 1 from one sin/cos each: bound 1e-15.
    EXPECT_LT((X.rotation() - test_formulas::rotation_z(angle)).norm(), 1e-15) << angle;
    EXPECT_EQ(X.translation(), Vector3::Zero());
    Vector6 axis;
    axis << 0, 0, 1, 0, 0, 0;
    EXPECT_EQ(Vector6(joint.motion_subspace(&angle)), axis);
  }
}

TEST(RevoluteJoint, WorldSubspaceOfAPendulumPinIsTheUserAxisThroughThePin) {
  const Model model = samples::planar_chain({{1.2, 2.0, 0.5, 0.3}, {0.8, 1.5, 0.4, 0.1}});
  Data data(model);
  VectorX q(2);
  q << 0.7, -1.9;
  update_positions(model, data, q);
  // Joint 2 turns about world +Y through its pin p2 = -1.2 (sin q1, 0, cos q1): the unit
  // twist about that line is [e_y; p2 x e_y] (Featherstone 2008, eq. 2.19).
  const Vector3 pin = -1.2 * Vector3(std::sin(q[0]), 0.0, std::cos(q[0]));
  Vector6 expected;
  expected << Vector3::UnitY(), pin.cross(Vector3::UnitY());
  EXPECT_LT((data.motion_subspace_world.col(1) - expected).norm(), 1e-14);
  expected << Vector3::UnitY(), Vector3::Zero();
  EXPECT_LT((data.motion_subspace_world.col(0) - expected).norm(), 1e-14);
}

}  // namespace
}  // namespace heavesim
