// Position and velocity stages against the closed-form kinematics of a planar double
// pendulum: body placements Ry(theta) at the pins, spatial velocities about the world
// origin.
#include <gtest/gtest.h>

#include <stdexcept>

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

// The position stage takes the revolute joints' cos and sin two joints at a time
// (libmvec) and an odd last one alone (libm): chains of one to five links, so that both
// paths place links, against the closed form Ry(theta_1 + ... + theta_k) and the pins
// summed link by link. Angles up to 39 rad (libmvec reduces them as libm does).
TEST(Kinematics, PlanarChainsOfOneToFiveRevoluteJointsMatchTheClosedForm) {
  for (int links = 1; links <= 5; ++links) {
    std::vector<samples::PlanarLink> chain;
    for (int k = 0; k < links; ++k) chain.push_back({0.5 + 0.25 * k, 1.0, 0.2, 0.1});
    const Model model = samples::planar_chain(chain);
    Data data(model);
    VectorX q(links);
    for (int k = 0; k < links; ++k) q[k] = (k % 2 ? -1.0 : 1.0) * (0.3 + 9.7 * k);
    update_positions(model, data, q);
    double theta = 0.0;
    Vector3 pin = Vector3::Zero();  // the upper pin of link k, in the world
    for (int k = 0; k < links; ++k) {
      theta += q[k];
      const Transform body = data.X_world_link[k + 1] * model.links[k + 1].X_link_body;
      // Entries of order 1; angles up to 39 rad, sums up to 20 rad (round-off ~20 eps).
      EXPECT_LT((body.rotation() - rotation_y(theta)).norm(), 1e-14) << links << " links, link " << k + 1;
      EXPECT_LT((body.translation() - pin).norm(), 1e-14) << links << " links, link " << k + 1;
      pin += -chain[k].length * Vector3(std::sin(theta), 0.0, std::cos(theta));
    }
  }
}

// The position stage places revolute joints from Model::revolute_coordinates (ModelBuilder
// sets it): a Data for a model whose list is missing is refused, rather than placing
// those joints unturned.
TEST(Kinematics, AModelWithoutItsRevoluteCoordinatesIsRefused) {
  Model model = samples::planar_chain({{1.0, 1.0, 0.5, 0.1}, {1.0, 1.0, 0.5, 0.1}});
  EXPECT_NO_THROW(Data{model});
  model.revolute_coordinates.pop_back();
  EXPECT_THROW(Data{model}, std::logic_error);
}

}  // namespace
}  // namespace heavesim
