// The universal (Hooke) joint against R = Rx(q0) Ry(q1) written out, and its motion
// subspace against the analytic derivative of that product: the child-side angular
// velocity is vee(R^T dR/dt), dR/dt = Rx'(q0) Ry(q1) qd0 + Rx(q0) Ry'(q1) qd1.
#include <gtest/gtest.h>

#include "kernel/joints/joint.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

using test_formulas::cross_matrix;
using test_formulas::rotation_x;
using test_formulas::rotation_y;

TEST(UniversalJoint, TransformAndSubspaceMatchTheProductOfTwoRotations) {
  const UniversalJoint joint;
  for (const auto& q : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.8, -0.3), Eigen::Vector2d(-2.2, 1.4)}) {
    const Transform X = joint.transform(q.data());
    const Matrix3 R = rotation_x(q[0]) * rotation_y(q[1]);
    EXPECT_LT((X.rotation() - R).norm(), 1e-15);
    EXPECT_EQ(X.translation(), Vector3::Zero());

    // d/dt Rx(a) = Rx(a) [e_x]x a', d/dt Ry(b) = Ry(b) [e_y]x b'.
    const Eigen::Vector2d rate(0.9, -1.7);
    const Matrix3 R_dot = rotation_x(q[0]) * cross_matrix(Vector3::UnitX()) * rotation_y(q[1]) * rate[0] +
                          rotation_x(q[0]) * rotation_y(q[1]) * cross_matrix(Vector3::UnitY()) * rate[1];
    Vector6 expected;
    expected << test_formulas::vee(R.transpose() * R_dot), Vector3::Zero();
    const Eigen::Matrix<double, 6, 2> S = joint.motion_subspace(q.data());
    // Products of a few order-1 factors: bound 1e-14.
    EXPECT_LT((S * rate - expected).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace heavesim
