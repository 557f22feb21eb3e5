// Kinetic and potential energy against the compound pendulum's textbook formulas.
#include <gtest/gtest.h>

#include <cmath>
#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "samples/planar_chains.hpp"

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

}  // namespace
}  // namespace heavesim
