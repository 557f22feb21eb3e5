// The fixed joint: no coordinates, identity transform; a tip mass welded to a
// pendulum adds I_tip + m_tip l^2 to the pendulum's inertia about its pin, and the
// weld carries the tip's weight and inertial force, m_tip (a_tip - g).
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/joints/joint.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim {
namespace {

TEST(FixedJoint, HasNoCoordinatesAndAnIdentityTransform) {
  const FixedJoint weld;
  EXPECT_EQ(FixedJoint::nq, 0);
  EXPECT_EQ(FixedJoint::nv, 0);
  const Transform X = weld.transform(nullptr);
  EXPECT_EQ(X.rotation(), Matrix3::Identity());
  EXPECT_EQ(X.translation(), Vector3::Zero());
}

/// A pendulum rod with a tip mass welded at its end: built here because only this
/// test welds a body to a pendulum (samples/ holds the models shared between callers).
Model pendulum_with_welded_tip(double rod_mass, double com, double rod_inertia, double length, double tip_mass,
                               double tip_inertia) {
  ModelBuilder builder;
  builder.add_body({"rod", Inertia(rod_mass, Vector3(0, 0, -com), Vector3(rod_inertia, rod_inertia, 0.0).asDiagonal()),
                    std::nullopt});
  builder.add_body({"tip", Inertia(tip_mass, Vector3::Zero(), Matrix3::Identity() * tip_inertia), std::nullopt});
  JointDefinition pin;
  pin.name = "pin";
  pin.axis = Vector3::UnitY();
  pin.parent = "ground";
  pin.child = "rod";
  builder.add_joint(pin);
  JointDefinition weld;
  weld.name = "weld";
  weld.kind = JointKind::fixed;
  weld.parent = "rod";
  weld.child = "tip";
  weld.X_parent_joint = Transform::from_translation(Vector3(0, 0, -length));
  builder.add_joint(weld);
  return builder.build();
}

TEST(FixedJoint, WeldedTipAddsItsInertiaAndCarriesItsInertialForce) {
  const double rod_mass = 2.0, com = 0.6, rod_inertia = 0.24, length = 1.2, tip_mass = 0.5, tip_inertia = 0.01;
  const double g = 9.81;
  const Model model = pendulum_with_welded_tip(rod_mass, com, rod_inertia, length, tip_mass, tip_inertia);
  ASSERT_EQ(model.nv, 1);
  Data data(model);
  const double angle = -0.9, rate = 2.1;
  update_positions(model, data, VectorX::Constant(1, angle));
  update_velocities(model, data, VectorX::Constant(1, angle), VectorX::Constant(1, rate));
  const double pin_inertia = rod_inertia + rod_mass * com * com + tip_inertia + tip_mass * length * length;
  EXPECT_NEAR(mass_matrix(model, data)(0, 0), pin_inertia, 1e-14 * pin_inertia);

  const double acceleration = articulated_body_forward_dynamics(model, data, VectorX::Zero(1))[0];
  const double expected_acceleration = -(rod_mass * com + tip_mass * length) * g * std::sin(angle) / pin_inertia;
  EXPECT_NEAR(acceleration, expected_acceleration, 1e-13);
  compute_joint_wrenches(model, data);
  // Tip at p = -l (sin q, 0, cos q): p'' = -l qdd (cos q, 0, -sin q) + l q'^2 (sin q, 0, cos q).
  const Vector3 tip_acceleration = -length * acceleration * Vector3(std::cos(angle), 0.0, -std::sin(angle)) +
                                   length * rate * rate * Vector3(std::sin(angle), 0.0, std::cos(angle));
  const JointReaction weld = joint_reaction(model, data, 2);
  // Forces of order 10 N: bound 1e-12 N.
  EXPECT_LT((weld.force_world - tip_mass * (tip_acceleration + g * Vector3::UnitZ())).norm(), 1e-12);
  // About the weld (at the tip's CoM) only the tip's own angular acceleration needs a moment.
  EXPECT_LT((weld.moment_world - tip_inertia * acceleration * Vector3::UnitY()).norm(), 1e-13);
}

}  // namespace
}  // namespace heavesim
