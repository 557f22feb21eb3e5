// Position and velocity stages against the closed-form kinematics of a planar double
// pendulum: body placements Ry(theta) at the pins, spatial velocities about the world
// origin.
#include <gtest/gtest.h>

#include "kernel/algorithms/kinematics.hpp"
#include "samples/planar_chains.hpp"
#include "tests/kernel/rotation_formulas.hpp"

namespace heavesim {
namespace {

using test_formulas::rotation_y;

TEST(Kinematics, DoublePendulumPlacementsAndVelocitiesMatchTheClosedForm) {
  const double upper_length = 1.2;
  const Model model = samples::planar_chain({{upper_length, 2.0, 0.5, 0.3}, {0.8, 1.5, 0.4, 0.1}});
  Data data(model);
  VectorX q(2), v(2);
  q << 0.7, -1.9;  // relative angles [rad]
  v << 1.3, 0.4;   // relative rates [rad/s]
  update_positions(model, data, q);
  update_velocities(model, data, q, v);

  // Absolute angles and rates; the upper link turns about the origin, the lower one
  // about the upper link's tip p2 = -L1 (sin theta1, 0, cos theta1).
  const double theta1 = q[0], theta2 = q[0] + q[1], rate1 = v[0], rate2 = v[0] + v[1];
  const Vector3 pin2 = -upper_length * Vector3(std::sin(theta1), 0.0, std::cos(theta1));
  const Vector3 pin2_velocity = -upper_length * rate1 * Vector3(std::cos(theta1), 0.0, -std::sin(theta1));
  const Transform body1 = data.X_world_link[1] * model.links[1].X_link_body;
  const Transform body2 = data.X_world_link[2] * model.links[2].X_link_body;
  // Entries of order 1 from a handful of products: round-off ~1e-16, bound 1e-14.
  EXPECT_LT((body1.rotation() - rotation_y(theta1)).norm(), 1e-14);
  EXPECT_LT(body1.translation().norm(), 1e-14);
  EXPECT_LT((body2.rotation() - rotation_y(theta2)).norm(), 1e-14);
  EXPECT_LT((body2.translation() - pin2).norm(), 1e-14);

  // Spatial velocity about the world origin: angular = rate about +Y; the velocity of
  // the body point at p is linear + angular x p.
  const Motion& velocity1 = data.velocity_world[1];
  const Motion& velocity2 = data.velocity_world[2];
  EXPECT_LT((velocity1.angular() - rate1 * Vector3::UnitY()).norm(), 1e-14);
  EXPECT_LT(velocity1.linear().norm(), 1e-14);  // link 1 turns about the origin itself
  EXPECT_LT((velocity2.angular() - rate2 * Vector3::UnitY()).norm(), 1e-14);
  EXPECT_LT((velocity2.linear() + velocity2.angular().cross(pin2) - pin2_velocity).norm(), 1e-14);
}

}  // namespace
}  // namespace heavesim
