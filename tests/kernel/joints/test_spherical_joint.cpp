// The spherical joint: quaternion integration stays on the unit sphere.
#include <gtest/gtest.h>

#include "kernel/joints/joint.hpp"

namespace heavesim {
namespace {

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
