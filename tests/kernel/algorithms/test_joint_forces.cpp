// Joint elements: a spring-mass oscillator follows x = A cos(w t) with the elastic
// energy 1/2 k A^2; a soft limit holds a weight at the static penetration m g / k and
// does nothing off the stop.
#include <gtest/gtest.h>

#include <cmath>
#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

TEST(Dynamics, SpringMassOscillatorFollowsTheClosedForm) {
  const double mass = 2.0, stiffness = 50.0, amplitude = 0.3, omega = std::sqrt(stiffness / mass);
  auto model = std::make_shared<const Model>(samples::prismatic_oscillator(mass, stiffness));
  MultibodySystem system(model);
  IntegratorSettings settings;
  settings.method = IntegrationMethod::dopri5;
  settings.relative_tolerance = settings.absolute_tolerance = 1e-12;
  auto integrator = make_integrator(settings);
  integrator->initialize(system, 0.0, system.initial_state(VectorX::Constant(1, amplitude), VectorX::Zero(1)));
  double max_error = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.1 * k;
    integrator->advance_to(t);
    max_error = std::max(max_error, std::abs(integrator->state()[0] - amplitude * std::cos(omega * t)));
  }
  EXPECT_LT(max_error, 1e-10);
  EXPECT_NEAR(joint_elastic_energy(*model, VectorX::Constant(1, amplitude)), 0.5 * stiffness * amplitude * amplitude,
              1e-15);
}

TEST(Dynamics, SoftLimitHoldsTheWeightAtTheStaticPenetration) {
  JointLimits limits;
  limits.lower = 0.0;
  limits.stiffness = 1e6;
  limits.damping = 0.0;
  const Model model = samples::prismatic_oscillator(10.0, 0.0, limits, Vector3(0, 0, -9.81));
  Data data(model);
  const double penetration = 10.0 * 9.81 / 1e6;
  const VectorX q = VectorX::Constant(1, -penetration), v = VectorX::Zero(1);
  VectorX tau = VectorX::Zero(1);
  add_joint_element_forces(model, q, v, tau);
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  EXPECT_NEAR(articulated_body_forward_dynamics(model, data, tau)[0], 0.0, 1e-12);
  // Above the stop the limit does nothing.
  tau.setZero();
  add_joint_element_forces(model, VectorX::Constant(1, 0.5), v, tau);
  EXPECT_EQ(tau[0], 0.0);
}

}  // namespace
}  // namespace heavesim
