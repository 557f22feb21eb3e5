// Prescribed motion (drivers) through the application: a rod pendulum hanging from a
// cart whose position is prescribed, x_s(t) = A sin(w t). The pendulum angle and the
// force the driver must apply are compared with Lagrange's equation for this system
// in its own coordinates, integrated by the independent reference integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "tests/test_support.hpp"
#include "validation/oracles/reference_integrator.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_drivers {
namespace {

constexpr double cart_mass = 3.0, rod_mass = 2.0, rod_length = 1.2, g = 9.81;
constexpr double amplitude = 0.4, frequency = 2.5;  // m, rad/s
constexpr double theta0 = 0.3;                       // rad

/// The case, with the driver's derivatives as expressions or left to the exact ones of position.
std::string write_case(const std::string& integrator, bool exact_derivatives) {
  const std::string derivatives = exact_derivatives ? "    velocity: A*w*cos(w*t)\n"
                                                      "    acceleration: -A*w^2*sin(w*t)\n"
                                                    : "";
  const std::string text = "name: driven_pendulum\n"
                           "parameters: {A: 0.4, w: 2.5, m: 2.0, L: 1.2}\n"
                           "bodies:\n"
                           "  - {name: cart, mass: 3.0, inertia: [0.1, 0.1, 0.1]}\n"
                           "  - {name: rod, mass: m, center_of_mass: [0, 0, -L/2], inertia: [m*L^2/12, m*L^2/12, 0]}\n"
                           "joints:\n"
                           "  - {name: rail, type: prismatic, parent: ground, child: cart, axis: [1, 0, 0]}\n"
                           "  - {name: pivot, type: revolute, parent: cart, child: rod, axis: [0, 1, 0], "
                           "initial: {q: 0.3}}\n"
                           "drivers:\n"
                           "  - name: shaker\n"
                           "    joint: rail\n"
                           "    position: A*sin(w*t)\n" +
                           derivatives + "solver: {integrator: " + integrator +
                           ", rtol: 1e-11, atol: 1e-12, step: 1e-3, t_end: 5}\n"
                           "output: {interval: 0.05}\n";
  const std::string path =
      (std::filesystem::temp_directory_path() /
       ("heavesim_driven_" + integrator + (exact_derivatives ? "_exact" : "_derived") + ".yaml"))
          .string();
  std::ofstream(path) << text;
  return path;
}

/// theta (from the downward vertical, about +y) and its rate, by Lagrange:
/// (I + m a^2) theta'' = m a cos(theta) x_s'' - m g a sin(theta), a = L/2, I = m L^2/12.
struct PendulumOracle {
  std::vector<double> times;
  std::vector<Eigen::VectorXd> states;
};
PendulumOracle pendulum_oracle(double t_end, double interval) {
  const double a = rod_length / 2, inertia = rod_mass * rod_length * rod_length / 12;
  PendulumOracle oracle;
  for (double t = interval; t < t_end + 1e-9; t += interval) oracle.times.push_back(t);
  const oracle::Rhs rhs = [=](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    const double x_dd = -amplitude * frequency * frequency * std::sin(frequency * t);
    ydot[0] = y[1];
    ydot[1] = (rod_mass * a * std::cos(y[0]) * x_dd - rod_mass * g * a * std::sin(y[0])) / (inertia + rod_mass * a * a);
  };
  oracle.states = oracle::integrate_reference(rhs, 0.0, Eigen::Vector2d(theta0, 0.0), oracle.times, 1e-13, 1e-14);
  return oracle;
}

/// Force along the rail the driver applies: M x'' + m (x'' - a cos(th) th'' + a sin(th) th'^2).
double driver_force(double t, double theta, double theta_dot) {
  const double a = rod_length / 2, inertia = rod_mass * rod_length * rod_length / 12;
  const double x_dd = -amplitude * frequency * frequency * std::sin(frequency * t);
  const double theta_dd =
      (rod_mass * a * std::cos(theta) * x_dd - rod_mass * g * a * std::sin(theta)) / (inertia + rod_mass * a * a);
  return cart_mass * x_dd +
         rod_mass * (x_dd - a * std::cos(theta) * theta_dd + a * std::sin(theta) * theta_dot * theta_dot);
}

void expect_matches_oracle(const std::string& integrator, bool exact_derivatives, double angle_tolerance,
                           double force_tolerance) {
  const CaseDefinition definition = load_case(write_case(integrator, exact_derivatives));
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  const int pivot = model.joint_index("pivot"), rail = model.joint_index("rail");
  const PendulumOracle oracle = pendulum_oracle(definition.solver.t_end, definition.output.interval);
  auto integrator_object = make_integrator(definition.solver.integrator, *scene.system);
  std::size_t sample = 0;
  double angle_error = 0.0, rate_error = 0.0, force_error = 0.0, cart_error = 0.0;
  run_simulation(scene, definition.solver, definition.output.interval, *integrator_object,
                 [&](double t, const VectorX& y) {
                   if (t == 0.0) return true;
                   scene.system->evaluate(t, y, true);
                   const Eigen::VectorXd& reference = oracle.states[sample++];
                   angle_error = std::max(angle_error, std::abs(y[model.joints[pivot].q_index] - reference[0]));
                   rate_error = std::max(rate_error,
                                         std::abs(y[model.nq + model.joints[pivot].v_index] - reference[1]));
                   cart_error = std::max(cart_error, std::abs(y[model.joints[rail].q_index] -
                                                              amplitude * std::sin(frequency * t)));
                   const double force = scene.system->data().constraint_multipliers[0];
                   force_error = std::max(force_error, std::abs(force - driver_force(t, reference[0], reference[1])));
                   return true;
                 });
  EXPECT_EQ(sample, oracle.times.size());
  EXPECT_LT(angle_error, angle_tolerance) << integrator;
  EXPECT_LT(rate_error, 10 * angle_tolerance) << integrator;
  EXPECT_LT(cart_error, 1e-9) << integrator;
  EXPECT_LT(force_error, force_tolerance) << integrator;
}

TEST(Drivers, ShakenPendulumMatchesLagrangeWithExactDerivatives) {
  // Tolerances: about 10x what was measured at rtol 1e-11 over 5 s (IDA 9e-10 rad and
  // 1.2e-8 N; Dormand-Prince 7e-12 rad, 1.7e-10 N; RK4 h = 1 ms 1.6e-11 rad, 3.6e-10 N;
  // the force swings about 20 N).
  expect_matches_oracle("ida", true, 1e-8, 1e-7);
  expect_matches_oracle("dopri5", true, 1e-10, 2e-9);
  expect_matches_oracle("rk4", true, 2e-10, 4e-9);
  // HHT is second order: at h = 1 ms it measured 1.05e-5 rad and 2.0e-4 N.
  expect_matches_oracle("hht", true, 3e-5, 6e-4);
}

TEST(Drivers, DerivativesOfThePositionExpressionAreAsGoodAsGivenOnes) {
  // Without velocity and acceleration the derivatives are the exact ones of A sin(w t)
  // (Taylor arithmetic): the same tolerances as with them given.
  expect_matches_oracle("dopri5", false, 1e-10, 2e-9);
}

TEST(Drivers, WrongDerivativeIsBadInput) {
  std::string path = write_case("dopri5", true);
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("A*w*cos(w*t)"), 12, "A*cos(w*t)  ");
  std::ofstream(path) << text;
  const testing::CommandResult result = testing::run_command_line(testing::heavesim_binary() + " check " + path);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("drivers[0].velocity"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("exact time derivative"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace heavesim::test_drivers
