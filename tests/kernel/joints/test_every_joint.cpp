// Properties every joint type shares, checked over all of them in one test each (the
// per-joint files beside this one hold each joint's closed forms): each joint's motion
// subspace S and bias c_J against central finite differences of its own transform
// X_J(q) along its manifold (q "+" v dt), and the configuration maps (derivative,
// integrate, difference) against each other; the builder's canonical frames against
// the user's geometry; the variant's sizes and names. The finite-difference test stays
// one test over all joints so that its seeded random sequence is unchanged.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/kinematics.hpp"
#include "kernel/joints/joint.hpp"
#include "kernel/model/model_builder.hpp"

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

  // The world-frame fast paths equal their definitions: X_world X_J and X_world S.
  Transform X_world_joint(axis_angle_rotation(Vector3(0.2, -0.6, 0.77).normalized(), 0.9), Vector3(0.3, -1.2, 2.0));
  Transform placed;
  joint.place(X_world_joint, q.data(), placed);
  EXPECT_TRUE(placed.is_approx(X_world_joint * X, 1e-14)) << J::type_name;
  Eigen::Matrix<double, 6, nv> S_world;
  joint.world_motion_subspace(placed, q.data(), S_world.data());
  for (int k = 0; k < nv; ++k)
    EXPECT_LT((S_world.col(k) - placed.act(Motion(S.col(k))).vector()).norm(), 1e-14) << J::type_name;

  // difference() inverts integrate().
  Eigen::Matrix<double, nv, 1> recovered;
  joint.difference(q0.data(), q.data(), recovered.data());
  EXPECT_LT((recovered - displacement).norm(), 1e-12) << J::type_name;
}

TEST(Joints, SubspaceBiasAndConfigurationMapsMatchFiniteDifferences) {
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 20; ++trial) {
    check_joint(RevoluteJoint{}, random);
    check_joint(PrismaticJoint{}, random);
    check_joint(CylindricalJoint{}, random);
    check_joint(UniversalJoint{}, random);
    check_joint(SphericalJoint{}, random);
    check_joint(FreeJoint{}, random);
  }
}

/// The builder turns joints with arbitrary axes into canonical ones; the user must
/// see the physics of the frames and axes they gave. A two-joint chain with
/// non-trivial frames on both sides of both joints: each body's world pose must be
/// the product of the user's transforms, X_parent_joint Rot(axis, q) X_child_joint^-1.
/// The two-body chain is built here: its frames exist only to exercise this test.
TEST(Joints, CanonicalFramesReproduceTheUserGeometry) {
  const Vector3 axis1 = Vector3(0.3, -0.5, 0.8).normalized(), axis2 = Vector3(-0.7, 0.1, 0.2).normalized();
  const Transform parent1(axis_angle_rotation(Vector3::UnitX(), 0.4), Vector3(0.1, 0.2, 0.3));
  const Transform child1(axis_angle_rotation(Vector3::UnitY(), -0.3), Vector3(-0.2, 0.0, 0.5));
  const Transform parent2(axis_angle_rotation(Vector3::UnitZ(), 1.1), Vector3(0.4, -0.3, 0.0));
  const Transform child2(axis_angle_rotation(Vector3(1, 1, 0).normalized(), 0.6), Vector3(0.0, 0.3, -0.1));
  const double q1 = 0.8, q2 = -0.35;
  for (JointKind kind : {JointKind::revolute, JointKind::prismatic, JointKind::cylindrical}) {
    ModelBuilder builder;
    for (int b = 1; b <= 2; ++b) {
      builder.add_body({"body" + std::to_string(b), Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
      JointDefinition joint;
      joint.name = "j" + std::to_string(b);
      joint.kind = kind;
      joint.axis = b == 1 ? axis1 : axis2;
      joint.parent = b == 1 ? "ground" : "body1";
      joint.child = "body" + std::to_string(b);
      joint.X_parent_joint = b == 1 ? parent1 : parent2;
      joint.X_child_joint = b == 1 ? child1 : child2;
      builder.add_joint(joint);
    }
    const Model model = builder.build();
    Data data(model);
    VectorX q = model.neutral_configuration();
    q[0] = q1;
    q[model.joints[2].q_index] = q2;
    update_positions(model, data, q);
    auto motion = [&](const Vector3& axis, double value) {
      if (kind == JointKind::prismatic) return Transform::from_translation(axis * value);
      return Transform::from_rotation(axis_angle_rotation(axis, value));  // cylindrical: the rotation coordinate
    };
    const Transform body1 = parent1 * motion(axis1, q1) * child1.inverse();
    const Transform body2 = body1 * parent2 * motion(axis2, q2) * child2.inverse();
    EXPECT_TRUE((data.X_world_link[1] * model.links[1].X_link_body).is_approx(body1, 1e-14));
    EXPECT_TRUE((data.X_world_link[2] * model.links[2].X_link_body).is_approx(body2, 1e-14));
    // The user's joint frame, recovered from the link frame, carries the user's axis.
    EXPECT_TRUE((model.joints[1].R_joint_link * Vector3::UnitZ()).isApprox(axis1, 1e-15));
  }
}

TEST(Joints, VariantReportsSizesAndNames) {
  EXPECT_EQ(joint_nq(JointType{FreeJoint{}}), 7);
  EXPECT_EQ(joint_nv(JointType{FreeJoint{}}), 6);
  EXPECT_EQ(joint_nv(JointType{FixedJoint{}}), 0);
  EXPECT_EQ(joint_type_name(JointType{UniversalJoint{}}), "universal");
  EXPECT_EQ(joint_type_name(canonical_joint_type(JointKind::cylindrical)), "cylindrical");
  EXPECT_FALSE(joint_has_scalar_coordinates(JointType{SphericalJoint{}}));
}

}  // namespace
}  // namespace heavesim
