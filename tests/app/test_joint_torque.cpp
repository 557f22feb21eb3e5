// The `joint_torque` force kind through the application, against closed forms: a rod
// on a revolute joint about z (no gravity) under a constant torque tau turns by
// theta(t) = tau t^2 / (2 I_O), under tau = a t by theta(t) = a t^3 / (6 I_O), with
// I_O = m L^2 / 3 the rod's inertia about its pivot; a cart on a prismatic joint under
// a force F moves by x(t) = F t^2 / (2 m).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/elements/joint_torque.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

constexpr double rod_mass = 2.0, rod_length = 1.5, cart_mass = 4.0;  // kg, m, kg

std::string write_case(const std::string& name, const std::string& torque, const std::string& cart_force) {
  const std::string text =
      "name: " + name +
      "\n"
      "parameters: {m: 2.0, L: 1.5, tau: 0.7, a: 3.0, F: 5.0}\n"
      "environment: {gravity: [0, 0, 0]}\n"
      "bodies:\n"
      "  - {name: rod, mass: m, center_of_mass: [L/2, 0, 0], inertia: [0, m*L^2/12, m*L^2/12]}\n"
      "  - {name: cart, mass: 4.0, inertia: [0.1, 0.1, 0.1]}\n"
      "joints:\n"
      "  - {name: pivot, type: revolute, parent: ground, child: rod, axis: [0, 0, 1]}\n"
      "  - {name: rail, type: prismatic, parent: ground, child: cart, axis: [1, 0, 0]}\n"
      "forces:\n"
      "  - {name: motor, type: joint_torque, joint: pivot, torque: " +
      torque +
      "}\n"
      "  - {name: pusher, type: joint_torque, joint: rail, coordinate: 0, torque: " +
      cart_force +
      "}\n"
      "solver: {integrator: dopri5, rtol: 1e-12, atol: 1e-14, t_end: 2}\n"
      "output: {interval: 0.1}\n";
  const std::string path = (std::filesystem::temp_directory_path() / ("heavesim_" + name + ".yaml")).string();
  std::ofstream(path) << text;
  return path;
}

/// Runs the case and returns the largest errors of the rod angle [rad] and the cart
/// position [m] against theta(t) and x(t).
std::pair<double, double> run_against(const std::string& path, const std::function<double(double)>& theta,
                                      const std::function<double(double)>& x) {
  const CaseDefinition definition = load_case(path);
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  const int pivot = model.joints[model.joint_index("pivot")].q_index;
  const int rail = model.joints[model.joint_index("rail")].q_index;
  auto integrator = make_integrator(definition.solver.integrator, *scene.system);
  double angle_error = 0.0, position_error = 0.0;
  int samples = 0;
  run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
    angle_error = std::max(angle_error, std::abs(y[pivot] - theta(t)));
    position_error = std::max(position_error, std::abs(y[rail] - x(t)));
    ++samples;
    return true;
  });
  EXPECT_EQ(samples, 21);
  return {angle_error, position_error};
}

const JointTorque& torque_element(const Scene& scene, const std::string& name) {
  for (const auto& element : scene.system->force_elements())
    if (element->name() == name) return dynamic_cast<const JointTorque&>(*element);
  throw std::runtime_error("no element " + name);
}

TEST(JointTorque, ConstantTorqueTurnsARodByTauTSquaredOverTwoI) {
  const double pivot_inertia = rod_mass * rod_length * rod_length / 3.0;
  const auto [angle_error, position_error] =
      run_against(write_case("joint_torque_constant", "tau", "F"),
                  [&](double t) { return 0.7 * t * t / (2.0 * pivot_inertia); },
                  [&](double t) { return 5.0 * t * t / (2.0 * cart_mass); });
  // Dormand-Prince integrates a quadratic exactly (up to round-off of the ~1 rad and
  // ~2.5 m values): 1e-12 leaves room for the step-size control's accumulation.
  EXPECT_LT(angle_error, 1e-12);
  EXPECT_LT(position_error, 1e-12);
}

TEST(JointTorque, TimeVaryingTorqueFollowsTheCubic) {
  const double pivot_inertia = rod_mass * rod_length * rod_length / 3.0;
  const auto [angle_error, position_error] =
      run_against(write_case("joint_torque_ramp", "a*t", "F*sin(t)"),
                  [&](double t) { return 3.0 * t * t * t / (6.0 * pivot_inertia); },
                  [&](double t) { return 5.0 * (t - std::sin(t)) / cart_mass; });
  // x'' = F sin(t) / m from rest: x = F (t - sin t) / m. Tolerances from rtol 1e-12 over
  // values of order 1.
  EXPECT_LT(angle_error, 1e-10);
  EXPECT_LT(position_error, 1e-10);
}

TEST(JointTorque, DependsOnTimeOnlyWhenTheExpressionReadsT) {
  const CaseDefinition definition = load_case(write_case("joint_torque_dependencies", "tau", "F*sin(2*t)"));
  Scene scene = build_scene(definition);
  const ElementDependencies constant = torque_element(scene, "motor").dependencies();
  EXPECT_FALSE(constant.time);
  EXPECT_FALSE(constant.configuration);
  EXPECT_FALSE(constant.velocity);
  EXPECT_FALSE(constant.element_states);
  EXPECT_TRUE(torque_element(scene, "pusher").dependencies().time);
  EXPECT_DOUBLE_EQ(torque_element(scene, "motor").torque(1.3), 0.7);
  EXPECT_DOUBLE_EQ(torque_element(scene, "pusher").torque(0.25), 5.0 * std::sin(0.5));
  // It adds exactly tau to its coordinate's generalized force and nothing else.
  const Model& model = *scene.model;
  scene.system->compute_stages_and_forces(0.25, scene.initial_state);
  const VectorX& joint_force = scene.system->applied_forces().joint_force;
  EXPECT_DOUBLE_EQ(joint_force[model.joints[model.joint_index("pivot")].v_index], 0.7);
  EXPECT_DOUBLE_EQ(joint_force[model.joints[model.joint_index("rail")].v_index], 5.0 * std::sin(0.5));
}

}  // namespace
}  // namespace heavesim
