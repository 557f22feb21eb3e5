// Kinetic and potential energy against the compound pendulum's textbook formulas, the
// quadratic form 1/2 v^T M v on random trees, and the sum of -m g . c over a planar
// chain's links written by hand; the kinetic energy refused without a current velocity stage.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "samples/planar_chains.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(Dynamics, EnergyOfAPendulumMatchesTheTextbookFormula) {
  const Model model = samples::pendulum(2.0, 0.6, 0.24);
  Data data(model);
  const double theta = 0.7, rate = -1.3;
  update_positions(model, data, VectorX::Constant(1, theta));
  update_velocities(model, data, VectorX::Constant(1, theta), VectorX::Constant(1, rate));
  // T = 1/2 (I_c + m a^2) w^2, V = -m g a cos(theta).
  EXPECT_NEAR(kinetic_energy(model, data), 0.5 * (0.24 + 2.0 * 0.36) * rate * rate, 1e-14);
  EXPECT_NEAR(gravity_potential_energy(model, data), -2.0 * 9.81 * 0.6 * std::cos(theta), 1e-13);
}

TEST(Energy, KineticEnergyIsHalfTheMassMatrixQuadraticForm) {
  std::mt19937_64 random(61);
  for (int trial = 0; trial < 6; ++trial) {
    samples::RandomTreeOptions options;
    options.bodies = 14;
    options.added_inertia = trial % 2 == 1;  // added mass enters T and M alike
    const Model model = samples::random_tree(random, options);
    Data data(model);
    const samples::RandomState state = samples::random_state(model, random);
    update_positions(model, data, state.q);
    update_velocities(model, data, state.q, state.v);
    const double kinetic = kinetic_energy(model, data);
    const double quadratic_form = 0.5 * state.v.dot(mass_matrix(model, data) * state.v);
    // Two sums of O(n^2) positive-definite terms of order 10 J: bound 1e-12 relative.
    EXPECT_NEAR(kinetic, quadratic_form, 1e-12 * quadratic_form) << "trial " << trial;
  }
}

TEST(Energy, KineticEnergyReadsTheCurrentVelocityStageOnly) {
  // It reads the momenta the velocity stage keeps: after a new position stage they belong
  // to the configuration before, and the read is refused rather than mixed.
  const Model model = samples::pendulum(2.0, 0.6, 0.24);
  Data data(model);
  update_positions(model, data, VectorX::Constant(1, 0.7));
  EXPECT_THROW(kinetic_energy(model, data), std::logic_error);
  update_velocities(model, data, VectorX::Constant(1, 0.7), VectorX::Constant(1, -1.3));
  EXPECT_NEAR(kinetic_energy(model, data), 0.5 * (0.24 + 2.0 * 0.36) * 1.69, 1e-14);
  update_positions(model, data, VectorX::Constant(1, 0.2));
  EXPECT_THROW(kinetic_energy(model, data), std::logic_error);
}

TEST(Energy, PotentialEnergyOfAPlanarChainSumsTheLinkHeights) {
  const std::vector<samples::PlanarLink> links = {{1.2, 2.0, 0.5, 0.3}, {0.8, 1.5, 0.4, 0.1}, {0.6, 0.7, 0.3, 0.02}};
  const Model model = samples::planar_chain(links);
  Data data(model);
  VectorX q(3);
  q << 0.4, -1.1, 2.3;
  update_positions(model, data, q);
  // Link i's CoM height: z_i = -(sum_{j<i} l_j cos theta_j + a_i cos theta_i), theta absolute.
  double expected = 0.0, pin_height = 0.0, theta = 0.0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    theta += q[static_cast<Eigen::Index>(i)];
    expected += links[i].mass * 9.81 * (pin_height - links[i].com * std::cos(theta));
    pin_height -= links[i].length * std::cos(theta);
  }
  // Terms of order 20 J: bound 1e-13 J.
  EXPECT_NEAR(gravity_potential_energy(model, data), expected, 1e-13);
}

}  // namespace
}  // namespace heavesim
