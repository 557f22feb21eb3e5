// Joint elements: a spring-mass oscillator follows x = A cos(w t) with the elastic
// energy 1/2 k A^2; a soft limit holds a weight at the static penetration m g / k and
// does nothing off the stop; the spring-dampers of a random tree's scalar joints give
// tau = -k (q - rest) - c v, coordinate by coordinate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernel/algorithms/articulated_body.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/oscillators.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(Dynamics, SpringMassOscillatorFollowsTheClosedForm) {
  const double mass = 2.0, stiffness = 50.0, amplitude = 0.3, omega = std::sqrt(stiffness / mass);
  auto model = std::make_shared<const Model>(samples::prismatic_oscillator(mass, stiffness));
  MultibodySystem system(model);
  IntegratorSettings settings;
  settings.method = IntegrationMethod::dopri5;
  settings.relative_tolerance = settings.absolute_tolerance = 1e-12;
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, system.initial_state(VectorX::Constant(1, amplitude), VectorX::Zero(1)));
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

TEST(JointForces, ScalarJointSpringDampersAreLinearInDisplacementAndRate) {
  std::mt19937_64 random(81);
  samples::RandomTreeOptions options;
  options.bodies = 21;
  const Model model = samples::random_tree(random, options);
  const samples::RandomState state = samples::random_state(model, random);
  VectorX tau = VectorX::Zero(model.nv);
  add_joint_element_forces(model, state.q, state.v, tau);
  VectorX expected = VectorX::Zero(model.nv);
  int springs = 0;
  for (int j = 1; j < model.num_links(); ++j) {
    const Joint& joint = model.joints[j];
    if (!joint.spring) continue;
    ASSERT_TRUE(joint_has_scalar_coordinates(joint.type)) << joint.name;
    ++springs;
    for (int k = 0; k < joint.nv; ++k) {
      const double displacement = state.q[joint.q_index + k] - joint.spring->rest[k];
      expected[joint.v_index + k] = -joint.spring->stiffness[k] * displacement - joint.spring->damping[k] * state.v[joint.v_index + k];
    }
  }
  EXPECT_GT(springs, 0);
  // Each entry is one product pair of order 10 N: bound 1e-13 N.
  EXPECT_LT((tau - expected).norm(), 1e-13);
  // The elastic energy is 1/2 k (q - rest)^2 summed over the same coordinates.
  double energy = 0.0;
  for (int j = 1; j < model.num_links(); ++j) {
    const Joint& joint = model.joints[j];
    if (!joint.spring) continue;
    for (int k = 0; k < joint.nv; ++k) {
      const double displacement = state.q[joint.q_index + k] - joint.spring->rest[k];
      energy += 0.5 * joint.spring->stiffness[k] * displacement * displacement;
    }
  }
  EXPECT_NEAR(joint_elastic_energy(model, state.q), energy, 1e-13 * (1.0 + energy));
}

}  // namespace
}  // namespace heavesim
