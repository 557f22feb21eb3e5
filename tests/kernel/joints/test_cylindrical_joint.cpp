// The cylindrical joint: rotation q0 about z and translation q1 along it, which
// commute: X_J = Rz(q0) with translation (0, 0, q1); S = [[e_z, 0]; [0, e_z]].
#include <gtest/gtest.h>

#include "kernel/joints/joint.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

TEST(CylindricalJoint, TransformIsARotationAndATranslationAlongZ) {
  const CylindricalJoint joint;
  for (const auto& q : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.8, -0.3), Eigen::Vector2d(-2.2, 4.0)}) {
    const Transform X = joint.transform(q.data());
    EXPECT_LT((X.rotation() - test_formulas::rotation_z(q[0])).norm(), 1e-15);
    EXPECT_EQ(X.translation(), Vector3(0.0, 0.0, q[1]));
    // The translation along the rotation axis commutes with the rotation: the same
    // pose whichever is applied first.
    const Transform rotate_then_slide = Transform::from_rotation(test_formulas::rotation_z(q[0])) *
                                        Transform::from_translation(Vector3(0.0, 0.0, q[1]));
    EXPECT_TRUE(X.is_approx(rotate_then_slide, 1e-15));
    Eigen::Matrix<double, 6, 2> S = Eigen::Matrix<double, 6, 2>::Zero();
    S(2, 0) = 1.0;
    S(5, 1) = 1.0;
    EXPECT_EQ((Eigen::Matrix<double, 6, 2>(joint.motion_subspace(q.data()))), S);
  }
}

}  // namespace
}  // namespace heavesim
