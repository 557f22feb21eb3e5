// Dynamics against closed forms that need no oracle machinery: a hanging chain's
// static reactions, a spring-mass oscillator, a soft limit stop, energy bookkeeping.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {
namespace {

BodyDefinition box(const std::string& name, double mass) {
  return {name, Inertia(mass, Vector3(0.0, 0.0, -0.5), Vector3(0.2, 0.3, 0.25).asDiagonal()), std::nullopt};
}

TEST(Dynamics, HangingChainAtRestCarriesTheWeightBelowEachJoint) {
  ModelBuilder builder;
  const double masses[3] = {2.0, 3.0, 5.0};
  for (int i = 0; i < 3; ++i) {
    builder.add_body(box("b" + std::to_string(i), masses[i]));
    JointDefinition joint;
    joint.name = "j" + std::to_string(i);
    joint.kind = i % 2 ? JointKind::spherical : JointKind::revolute;
    joint.axis = Vector3::UnitX();
    joint.parent = i == 0 ? "ground" : "b" + std::to_string(i - 1);
    joint.child = "b" + std::to_string(i);
    joint.X_parent_joint = Transform::from_translation(Vector3(0, 0, i == 0 ? 0.0 : -1.0));
    builder.add_joint(joint);
  }
  const Model model = builder.build();
  Data data(model);
  const VectorX q = model.neutral_configuration(), v = VectorX::Zero(model.nv);
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  const VectorX qdd = articulated_body_forward_dynamics(model, data, VectorX::Zero(model.nv));
  EXPECT_LT(qdd.norm(), 1e-14);
  compute_joint_wrenches(model, data);
  for (int i = 0; i < 3; ++i) {
    double weight_below = 0.0;
    for (int j = i; j < 3; ++j) weight_below += masses[j] * 9.81;
    const JointReaction reaction = joint_reaction(model, data, i + 1);
    EXPECT_NEAR(reaction.force_world.z(), weight_below, 1e-12 * weight_below);
    EXPECT_NEAR(reaction.force_world.head<2>().norm(), 0.0, 1e-12);
    EXPECT_NEAR(reaction.moment_world.norm(), 0.0, 1e-12);  // every CoM is straight below its joint
  }
}

/// One body on a vertical prismatic joint with a spring; no gravity.
Model oscillator(double mass, double stiffness, std::optional<JointLimits> limits = std::nullopt,
                 Vector3 gravity = Vector3::Zero()) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  builder.add_body({"mass", Inertia(mass, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  JointDefinition joint;
  joint.name = "slide";
  joint.kind = JointKind::prismatic;
  joint.parent = "ground";
  joint.child = "mass";
  joint.limits = limits;
  if (stiffness > 0.0)
    joint.spring = JointSpringDamper{JointVector::Constant(1, stiffness), JointVector::Zero(1), JointVector::Zero(1)};
  builder.add_joint(joint);
  return builder.build();
}

TEST(Dynamics, SpringMassOscillatorFollowsTheClosedForm) {
  const double mass = 2.0, stiffness = 50.0, amplitude = 0.3, omega = std::sqrt(stiffness / mass);
  auto model = std::make_shared<const Model>(oscillator(mass, stiffness));
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
  const Model model = oscillator(10.0, 0.0, limits, Vector3(0, 0, -9.81));
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

TEST(Dynamics, EnergyOfAPendulumMatchesTheTextbookFormula) {
  ModelBuilder builder;
  builder.add_body({"rod", Inertia(2.0, Vector3(0, 0, -0.6), Vector3(0.24, 0.24, 0.0).asDiagonal()), std::nullopt});
  JointDefinition pin;
  pin.name = "pin";
  pin.axis = Vector3::UnitY();
  pin.parent = "ground";
  pin.child = "rod";
  builder.add_joint(pin);
  const Model model = builder.build();
  Data data(model);
  const double theta = 0.7, rate = -1.3;
  update_positions(model, data, VectorX::Constant(1, theta));
  update_velocities(model, data, VectorX::Constant(1, theta), VectorX::Constant(1, rate));
  // T = 1/2 (I_c + m a^2) w^2, V = -m g a cos(theta).
  EXPECT_NEAR(kinetic_energy(model, data), 0.5 * (0.24 + 2.0 * 0.36) * rate * rate, 1e-14);
  EXPECT_NEAR(gravity_potential_energy(model, data), -2.0 * 9.81 * 0.6 * std::cos(theta), 1e-13);
}

TEST(Dynamics, NonFiniteAccelerationStopsWithADiagnosisNamingTheJoint) {
  auto model = std::make_shared<const Model>(oscillator(1.0, 1e300));
  MultibodySystem system(model);
  VectorX y = system.initial_state(VectorX::Constant(1, 1e300), VectorX::Zero(1)), ydot(2);
  try {
    system.state_derivative(0.0, y, ydot);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("joint 'slide'"), std::string::npos) << error.what();
    EXPECT_FALSE(error.suggestion().empty());
  }
}

}  // namespace
}  // namespace heavesim
