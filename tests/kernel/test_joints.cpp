// Each joint's motion subspace S and bias c_J against central finite differences of
// its own transform X_J(q) along its manifold (q "+" v dt), and the configuration
// maps (derivative, integrate, difference) against each other.
#include <gtest/gtest.h>

#include <random>

#include "kernel/joints/joint.hpp"

namespace heavesim {
namespace {

/// Spatial velocity of the child-side frame, child coordinates, from X(t-h), X(t+h):
/// [R^T dR/dt (vee); R^T dp/dt].
Vector6 relative_velocity(const Transform& before, const Transform& after, const Transform& now, double h) {
  const Matrix3 R_dot = (after.rotation() - before.rotation()) / (2 * h);
  const Vector3 p_dot = (after.translation() - before.translation()) / (2 * h);
  const Matrix3 W = now.rotation().transpose() * R_dot;
  Vector6 v;
  v << W(2, 1), W(0, 2), W(1, 0), now.rotation().transpose() * p_dot;
  return v;
}

template <class J>
void check_joint(const J& joint, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  constexpr int nq = J::nq, nv = J::nv;
  Eigen::Matrix<double, nq, 1> q0;
  joint.neutral(q0.data());
  Eigen::Matrix<double, nv, 1> displacement, v;
  for (int i = 0; i < nv; ++i) {
    displacement[i] = uniform(random);
    v[i] = uniform(random);
  }
  Eigen::Matrix<double, nq, 1> q;
  joint.integrate(q0.data(), displacement.data(), 1.0, q.data());

  const double h = 1e-6;
  auto at = [&](double t) {
    Eigen::Matrix<double, nq, 1> qt;
    joint.integrate(q.data(), v.data(), t, qt.data());
    return qt;
  };
  const Transform X = joint.transform(q.data());
  const Eigen::Matrix<double, nq, 1> q_before = at(-h), q_after = at(h);
  const Vector6 measured = relative_velocity(joint.transform(q_before.data()), joint.transform(q_after.data()), X, h);
  const MotionSubspace<nv> S = joint.motion_subspace(q.data());
  EXPECT_LT((S * v - measured).norm(), 1e-8) << J::type_name;

  // c_J = dS/dt v along the motion, by differencing S.
  const MotionSubspace<nv> S_before = joint.motion_subspace(q_before.data()),
                           S_after = joint.motion_subspace(q_after.data());
  const Vector6 bias_measured = (S_after - S_before) / (2 * h) * v;
  const Vector6 bias = J::has_bias_acceleration ? joint.bias_acceleration(q.data(), v.data()).vector()
                                                : Vector6(Vector6::Zero());
  EXPECT_LT((bias - bias_measured).norm(), 1e-7) << J::type_name;

  // qdot = N(q) v agrees with the time derivative of q along integrate().
  Eigen::Matrix<double, nq, 1> qdot;
  joint.configuration_derivative(q.data(), v.data(), qdot.data());
  EXPECT_LT((qdot - (q_after - q_before) / (2 * h)).norm(), 1e-8) << J::type_name;

  // difference() inverts integrate().
  Eigen::Matrix<double, nv, 1> recovered;
  joint.difference(q0.data(), q.data(), recovered.data());
  EXPECT_LT((recovered - displacement).norm(), 1e-12) << J::type_name;
}

TEST(Joints, SubspaceBiasAndConfigurationMapsMatchFiniteDifferences) {
  std::mt19937_64 random(7);
  const Vector3 axis = Vector3(0.3, -0.5, 0.8).normalized();
  for (int trial = 0; trial < 20; ++trial) {
    check_joint(RevoluteJoint{axis}, random);
    check_joint(PrismaticJoint{axis}, random);
    check_joint(CylindricalJoint{axis}, random);
    check_joint(UniversalJoint{axis, axis.unitOrthogonal()}, random);
    check_joint(SphericalJoint{}, random);
    check_joint(FreeJoint{}, random);
  }
}

TEST(Joints, QuaternionJointsStayOnTheUnitSphere) {
  const SphericalJoint ball;
  double q[4];
  ball.neutral(q);
  const double v[3] = {3.0, -2.0, 5.0};
  for (int step = 0; step < 10000; ++step) ball.integrate(q, v, 0.01, q);
  EXPECT_NEAR(Eigen::Map<Eigen::Vector4d>(q).norm(), 1.0, 1e-14);
}

TEST(Joints, VariantReportsSizesAndNames) {
  EXPECT_EQ(joint_nq(JointType{FreeJoint{}}), 7);
  EXPECT_EQ(joint_nv(JointType{FreeJoint{}}), 6);
  EXPECT_EQ(joint_nv(JointType{FixedJoint{}}), 0);
  EXPECT_EQ(joint_type_name(JointType{UniversalJoint{}}), "universal");
  EXPECT_FALSE(joint_has_scalar_coordinates(JointType{SphericalJoint{}}));
}

}  // namespace
}  // namespace heavesim
