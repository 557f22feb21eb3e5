// Recursive Newton-Euler inverse dynamics against closed forms: a compound pendulum,
// tau = (I_c + m a^2) qdd + m g a sin(q), and two stacked vertical sliders, whose
// joint forces are the weights and inertial forces of what each joint carries.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/algorithms/inverse_dynamics.hpp"
#include "samples/oscillators.hpp"
#include "samples/planar_chains.hpp"

namespace heavesim {
namespace {

TEST(InverseDynamics, CompoundPendulumTorqueIsTheTextbookFormula) {
  const double mass = 2.0, com = 0.6, inertia = 0.24, g = 9.81;
  const Model model = samples::pendulum(mass, com, inertia);
  Data data(model);
  for (const double angle : {0.0, 0.7, -2.5}) {
    const double rate = -1.3, acceleration = 0.8;
    const double tau = rnea(model, data, VectorX::Constant(1, angle), VectorX::Constant(1, rate),
                            VectorX::Constant(1, acceleration))[0];
    // The velocity term vanishes: a pure rotation about a fixed axis through the pin.
    const double expected = (inertia + mass * com * com) * acceleration + mass * g * com * std::sin(angle);
    // Terms of order 10 N m summed over a few operations: round-off ~1e-15, bound 1e-13.
    EXPECT_NEAR(tau, expected, 1e-13) << "q = " << angle;
  }
}

TEST(InverseDynamics, StackedSlidersCarryTheWeightAndInertiaAboveThem) {
  const double base_mass = 7.0, load_mass = 3.0, g = 9.81;
  auto model = samples::base_and_load(base_mass, load_mass);
  Data data(*model);
  VectorX q(2), v(2), qdd(2);
  q << 0.4, -0.2;
  v << 1.5, -0.7;
  qdd << 0.9, -2.1;
  const VectorX tau = rnea(*model, data, q, v, qdd);
  // Heave carries both bodies; the stroke carries the load, whose absolute
  // acceleration is the sum of both joint accelerations (gravity along -Z).
  const double heave = (base_mass + load_mass) * (qdd[0] + g) + load_mass * qdd[1];
  const double stroke = load_mass * (qdd[0] + qdd[1] + g);
  // Forces of order 100 N: bound 1e-12 N (a few ulps of the largest term).
  EXPECT_NEAR(tau[0], heave, 1e-12);
  EXPECT_NEAR(tau[1], stroke, 1e-12);
}

}  // namespace
}  // namespace heavesim
