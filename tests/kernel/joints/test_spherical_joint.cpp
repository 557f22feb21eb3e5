// The spherical joint's quaternion kinematics against Rodrigues' formula written in
// the test: the transform of q = (cos t/2, sin t/2 n) is the rotation by t about n,
// and integrating a constant body angular velocity w for time t from identity gives
// the rotation by |w| t about w. Integration stays on the unit sphere.
#include <gtest/gtest.h>

#include "kernel/joints/joint.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

using test_formulas::rodrigues;

TEST(SphericalJoint, TransformOfAQuaternionIsRodriguesRotation) {
  const SphericalJoint ball;
  const Vector3 axis = Vector3(0.3, -0.8, 0.52).normalized();
  for (const double angle : {0.3, 1.9, 3.1}) {
    const double q[4] = {std::cos(angle / 2), std::sin(angle / 2) * axis.x(), std::sin(angle / 2) * axis.y(),
                         std::sin(angle / 2) * axis.z()};
    const Transform X = ball.transform(q);
    // Entries of order 1 from products of sines: bound 1e-15 per entry, 1e-14 in norm.
    EXPECT_LT((X.rotation() - rodrigues(angle * axis)).norm(), 1e-14) << angle;
    EXPECT_EQ(X.translation(), Vector3::Zero());
  }
}

TEST(SphericalJoint, ConstantAngularVelocityIntegratesToRodriguesRotation) {
  const SphericalJoint ball;
  double neutral[4];
  ball.neutral(neutral);
  const double rate[3] = {0.7, -1.1, 0.4};  // rad/s, child axes
  const Vector3 w(rate[0], rate[1], rate[2]);
  for (const double time : {0.1, 1.0, 2.5}) {
    double q[4];
    ball.integrate(neutral, rate, time, q);
    EXPECT_LT((ball.transform(q).rotation() - rodrigues(w * time)).norm(), 1e-14) << time;
  }
  // From a rotated start, body-frame integration composes on the right: R0 exp(w t).
  const double start[4] = {std::cos(0.4), std::sin(0.4), 0.0, 0.0};  // 0.8 rad about x
  double q[4];
  ball.integrate(start, rate, 0.6, q);
  EXPECT_LT((ball.transform(q).rotation() - rodrigues(0.8 * Vector3::UnitX()) * rodrigues(0.6 * w)).norm(), 1e-14);
}

TEST(Joints, QuaternionJointsStayOnTheUnitSphere) {
  const SphericalJoint ball;
  double q[4];
  ball.neutral(q);
  const double v[3] = {3.0, -2.0, 5.0};
  for (int step = 0; step < 10000; ++step) ball.integrate(q, v, 0.01, q);
  EXPECT_NEAR(Eigen::Map<Eigen::Vector4d>(q).norm(), 1.0, 1e-14);
}

}  // namespace
}  // namespace heavesim
