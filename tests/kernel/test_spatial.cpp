// Spatial algebra against the explicit 6x6 matrices of Featherstone (2008), ch. 2,
// written out independently here.
#include <gtest/gtest.h>

#include <random>

#include "kernel/spatial/inertia.hpp"
#include "kernel/spatial/rotation.hpp"

namespace heavesim {
namespace {

Matrix6 crm(const Vector6& v) {  // motion cross-product matrix, eq. 2.31
  Matrix6 m = Matrix6::Zero();
  m.topLeftCorner<3, 3>() = skew(v.head<3>());
  m.bottomLeftCorner<3, 3>() = skew(v.tail<3>());
  m.bottomRightCorner<3, 3>() = skew(v.head<3>());
  return m;
}
Matrix6 crf(const Vector6& v) { return -crm(v).transpose(); }  // eq. 2.32

class SpatialTest : public ::testing::Test {
 protected:
  std::mt19937_64 random{42};
  Vector6 random6() { return Vector6::NullaryExpr([&](Eigen::Index) { return uniform(random); }); }
  Transform random_transform() {
    Eigen::Quaterniond q(uniform(random), uniform(random), uniform(random), uniform(random));
    return Transform(q.normalized().toRotationMatrix(), Vector3(uniform(random), uniform(random), uniform(random)));
  }
  std::uniform_real_distribution<double> uniform{-1.0, 1.0};
};

TEST_F(SpatialTest, CrossProductsMatchTheirMatrixForms) {
  for (int trial = 0; trial < 100; ++trial) {
    const Vector6 v = random6(), m = random6(), f = random6();
    EXPECT_TRUE(Motion(v).cross(Motion(m)).vector().isApprox(crm(v) * m, 1e-14));
    EXPECT_TRUE(Motion(v).cross(Force(f)).vector().isApprox(crf(v) * f, 1e-14));
  }
}

TEST_F(SpatialTest, TransformActsLikeFeatherstonesPluckerMatrix) {
  for (int trial = 0; trial < 100; ++trial) {
    const Transform X = random_transform();
    // ^A X_B for motions: [E 0; -E rx ... ] written from the point-velocity rule v_A = R v_B + p x (R w_B).
    Matrix6 X_motion = Matrix6::Zero();
    X_motion.topLeftCorner<3, 3>() = X.rotation();
    X_motion.bottomLeftCorner<3, 3>() = skew(X.translation()) * X.rotation();
    X_motion.bottomRightCorner<3, 3>() = X.rotation();
    const Matrix6 X_force = X_motion.inverse().transpose();  // eq. 2.26: X* = X^-T
    const Vector6 m = random6(), f = random6();
    EXPECT_TRUE(X.act(Motion(m)).vector().isApprox(X_motion * m, 1e-13));
    EXPECT_TRUE(X.act(Force(f)).vector().isApprox(X_force * f, 1e-13));
    EXPECT_TRUE(X.act_inverse(X.act(Motion(m))).vector().isApprox(m, 1e-13));
    EXPECT_TRUE(X.act_inverse(X.act(Force(f))).vector().isApprox(f, 1e-13));
    // Power is frame independent.
    EXPECT_NEAR(dot(X.act(Motion(m)), X.act(Force(f))), dot(Motion(m), Force(f)), 1e-13);
    EXPECT_TRUE(X.motion_matrix().isApprox(X_motion, 1e-14));
  }
}

TEST_F(SpatialTest, CompositionAndInverse) {
  const Transform A = random_transform(), B = random_transform();
  const Vector6 m = random6();
  EXPECT_TRUE((A * B).act(Motion(m)).vector().isApprox(A.act(B.act(Motion(m))).vector(), 1e-13));
  EXPECT_TRUE((A * A.inverse()).is_approx(Transform::Identity(), 1e-14));
}

TEST_F(SpatialTest, RigidInertiaMatrixAndProduct) {
  for (int trial = 0; trial < 50; ++trial) {
    const double mass = 1.0 + uniform(random) * 0.5;
    const Vector3 c(uniform(random), uniform(random), uniform(random));
    Matrix3 I_c;
    I_c << 2.0, 0.1, -0.2, 0.1, 1.5, 0.05, -0.2, 0.05, 1.8;
    const Inertia inertia(mass, c, I_c);
    // Eq. 2.63 written out: I = [I_c + m C C^T, m C; m C^T, m 1], C = skew(c).
    Matrix6 expected;
    expected << I_c + mass * skew(c) * skew(c).transpose(), mass * skew(c), mass * skew(c).transpose(),
        mass * Matrix3::Identity();
    EXPECT_TRUE(inertia.matrix().isApprox(expected, 1e-14));
    const Vector6 v = random6();
    EXPECT_TRUE((inertia * Motion(v)).vector().isApprox(expected * v, 1e-14));
    EXPECT_NEAR(inertia.kinetic_energy(Motion(v)), 0.5 * v.dot(expected * v), 1e-13);
  }
}

TEST_F(SpatialTest, InertiaTransformsAsXStarIXInverse) {
  for (int trial = 0; trial < 50; ++trial) {
    const Transform X = random_transform();
    const Matrix6 X_motion_inverse = X.motion_matrix().inverse();
    const Matrix6 X_force = X_motion_inverse.transpose();
    Matrix3 I_c;
    I_c << 2.0, 0.1, -0.2, 0.1, 1.5, 0.05, -0.2, 0.05, 1.8;
    const Inertia inertia(1.7, Vector3(0.1, -0.3, 0.2), I_c);
    const Matrix6 expected = X_force * inertia.matrix() * X_motion_inverse;
    EXPECT_TRUE(inertia.transformed(X).matrix().isApprox(expected, 1e-13));
    // A general symmetric 6x6 (e.g. with added mass) by the block formula.
    Matrix6 general = Matrix6::Random();
    general = (general * general.transpose()).eval();
    EXPECT_TRUE(transform_spatial_inertia(X, general).isApprox(X_force * general * X_motion_inverse, 1e-12));
  }
}

TEST_F(SpatialTest, SumOfInertiasIsSumOfMatrices) {
  Matrix3 I1 = Vector3(1.0, 2.0, 1.5).asDiagonal(), I2 = Vector3(0.3, 0.4, 0.5).asDiagonal();
  const Inertia a(2.0, Vector3(0.1, 0.2, 0.3), I1), b(3.0, Vector3(-0.5, 0.4, 0.0), I2);
  EXPECT_TRUE((a + b).matrix().isApprox(a.matrix() + b.matrix(), 1e-14));
}

// The additive form about the origin (CRBA's composite inertias) against eq. 2.63's
// matrix of the same body moved by X (X* I X^-1): its matrix, its product with a
// motion, and the sum of two bodies.
TEST_F(SpatialTest, InertiaAboutTheOriginIsEquation263AndAdds) {
  for (int trial = 0; trial < 50; ++trial) {
    const Transform X = random_transform();
    const Matrix6 X_motion_inverse = X.motion_matrix().inverse();
    Matrix3 I_c;
    I_c << 2.0, 0.1, -0.2, 0.1, 1.5, 0.05, -0.2, 0.05, 1.8;
    const Inertia body(1.7, Vector3(0.1, -0.3, 0.2), I_c);
    const Matrix6 expected = X_motion_inverse.transpose() * body.matrix() * X_motion_inverse;
    const InertiaAboutOrigin about_origin(body.transformed(X));
    EXPECT_TRUE(about_origin.matrix().isApprox(expected, 1e-13));
    const Vector6 v = random6();
    EXPECT_TRUE((about_origin * Motion(v)).vector().isApprox(expected * v, 1e-13));
    const Inertia other(0.4, Vector3(-0.2, 0.5, 0.1), Vector3(0.3, 0.2, 0.25).asDiagonal());
    InertiaAboutOrigin sum = about_origin;
    sum += InertiaAboutOrigin(other);
    EXPECT_TRUE(sum.matrix().isApprox(expected + other.matrix(), 1e-13));
  }
}

TEST_F(SpatialTest, QuaternionDerivativeIsHalfQTimesOmega) {
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2).normalized();
  const Vector3 omega(0.4, -1.1, 0.8);
  Eigen::Vector4d wxyz(q.w(), q.x(), q.y(), q.z()), rate;
  quaternion_derivative(wxyz, omega, rate);
  const Eigen::Quaterniond expected = q * Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z());
  EXPECT_NEAR(rate[0], 0.5 * expected.w(), 1e-15);
  EXPECT_NEAR(rate[1], 0.5 * expected.x(), 1e-15);
  EXPECT_NEAR(rate[2], 0.5 * expected.y(), 1e-15);
  EXPECT_NEAR(rate[3], 0.5 * expected.z(), 1e-15);
  // Off the unit sphere the correction term points back to it.
  Eigen::Vector4d scaled = 1.1 * wxyz;
  quaternion_derivative(scaled, Vector3::Zero(), rate);
  EXPECT_LT(rate.dot(scaled), 0.0);
}

}  // namespace
}  // namespace heavesim
