// The free joint: the transform is the quaternion's rotation (Rodrigues' formula) and
// the position; integrating a constant body velocity that surges at u while yawing at
// r draws the circle of radius u / r written out in the test.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/joints/joint.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

TEST(FreeJoint, TransformIsTheQuaternionRotationAndThePosition) {
  const FreeJoint joint;
  const Vector3 axis = Vector3(-0.2, 0.9, 0.4).normalized();
  const double angle = 2.2;
  const double q[7] = {1.5, -0.5, 2.0, std::cos(angle / 2), std::sin(angle / 2) * axis.x(),
                       std::sin(angle / 2) * axis.y(), std::sin(angle / 2) * axis.z()};
  const Transform X = joint.transform(q);
  EXPECT_LT((X.rotation() - test_formulas::rodrigues(angle * axis)).norm(), 1e-14);
  EXPECT_EQ(X.translation(), Vector3(1.5, -0.5, 2.0));
}

TEST(FreeJoint, SurgeWhileYawingDrawsACircle) {
  const FreeJoint joint;
  double q0[7];
  joint.neutral(q0);
  const double surge = 2.0, yaw_rate = 0.5;             // m/s, rad/s (body axes)
  const double v[6] = {0, 0, yaw_rate, surge, 0, 0};  // [angular; linear]
  for (const double time : {0.5, 2.0, 9.0}) {
    double q[7];
    joint.integrate(q0, v, time, q);
    // Heading psi = r t; position (u / r)(sin psi, 1 - cos psi, 0).
    const double heading = yaw_rate * time, radius = surge / yaw_rate;
    const Vector3 expected(radius * std::sin(heading), radius * (1.0 - std::cos(heading)), 0.0);
    const Transform X = joint.transform(q);
    // Positions of order 4 m: bound 1e-14 relative, 1e-13 m.
    EXPECT_LT((X.translation() - expected).norm(), 1e-13) << time;
    EXPECT_LT((X.rotation() - test_formulas::rotation_z(heading)).norm(), 1e-14) << time;
  }
}

}  // namespace
}  // namespace heavesim
