// The driver kinds on frames (absolute, distance, angle) through the application: a
// case that uses each is read, built and run, and the motion and the actuator force the
// run finds are compared with closed forms written here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/projection.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_driver_kinds {
namespace {

std::string write_case(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / ("heavesim_driver_kinds_" + name + ".yaml")).string();
  std::ofstream(path) << text;
  return path;
}

// A 2 kg block on a rail along d = (0.6, 0, 0.8) (world), its point driven along d by an
// absolute driver: s(t) = 1 + 0.5 sin(2 t). Along the rail m s'' = lambda + m g . d, so
// the driver's force (its multiplier, along d) is lambda = m s'' - m g . d.
constexpr double block_mass = 2.0, g = 9.81;
const Vector3 rail_direction(0.6, 0.0, 0.8);
double rail_position(double t) { return 1.0 + 0.5 * std::sin(2.0 * t); }
double rail_acceleration(double t) { return -2.0 * std::sin(2.0 * t); }

const char* const block_on_inclined_rail =
    "name: block_on_inclined_rail\n"
    "bodies:\n"
    "  - {name: block, mass: 2.0, inertia: [0.1, 0.1, 0.1]}\n"
    "joints:\n"
    "  - {name: rail, type: prismatic, parent: ground, child: block, axis: [0.6, 0, 0.8], initial: {q: 1}}\n"
    "drivers:\n"
    "  - name: block_s\n"
    "    type: absolute\n"
    "    body: block\n"
    "    point: [0, 0, 0]\n"
    "    direction: [0.6, 0, 0.8]\n"
    "    position: 1 + 0.5*sin(2*t)\n"
    "    velocity: cos(2*t)\n"
    "    acceleration: -2*sin(2*t)\n"
    "solver: {integrator: dopri5, rtol: 1e-11, atol: 1e-12, t_end: 3}\n"
    "output: {interval: 0.05}\n";

TEST(DriverKinds, AbsoluteDriverMovesABlockOnARailWithTheForceNewtonGives) {
  const CaseDefinition definition = load_case(write_case("absolute", block_on_inclined_rail));
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  ASSERT_EQ(model.constraints.size(), 1u);
  EXPECT_STREQ(model.constraints[0].kind_name(), "absolute driver");
  EXPECT_EQ(describe_constraint_row(model, 0),
            "absolute driver 'block_s': component along (0.6, 0, 0.8) of block's point (0, 0, 0)");
  const int rail = model.joint_index("rail");
  auto integrator = make_integrator(definition.solver.integrator, *scene.system);
  int samples = 0;
  double position_error = 0.0, force_error = 0.0;
  const RunOutcome outcome = run_simulation(
      scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
        scene.system->evaluate(t, y, true);
        position_error = std::max(position_error, std::abs(y[model.joints[rail].q_index] - rail_position(t)));
        const double expected_force =
            block_mass * rail_acceleration(t) - block_mass * Vector3(0, 0, -g).dot(rail_direction);
        force_error = std::max(force_error, std::abs(scene.system->data().constraint_multipliers[0] - expected_force));
        ++samples;
        return true;
      });
  EXPECT_TRUE(outcome.completed);
  EXPECT_EQ(samples, 61);
  // The coordinate is held by the constraint (projection to 1e-10 m by default; the
  // integrator's error is far below it at rtol 1e-11); the force is m s'' + 15.7 N,
  // solved from a 1x1 KKT system: round-off of ~10 ulp of 20 N.
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(force_error, 1e-11 * 20.0 * 100);
}

/// Runs the case through `heavesim run` and returns the result file's path.
std::string run_case(const std::string& name, const std::string& text) {
  const std::string output = temporary(name + ".h5");
  const testing::CommandResult result =
      testing::run_command_line(testing::heavesim_binary() + " run " + write_case(name, text) + " -o " + output + " -q");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return output;
}

TEST(DriverKinds, AbsoluteDriverForceIsRecordedUnderDrivers) {
  H5File file(run_case("absolute_file", block_on_inclined_rail));
  ASSERT_TRUE(file.ok());
  EXPECT_FALSE(file.exists("/constraints/block_s"));  // drivers are recorded in /drivers only
  const std::vector<double> time = file.read("/time"), force = file.read("/drivers/block_s/force");
  const std::vector<double> position = file.read("/drivers/block_s/position");
  const std::vector<double> velocity = file.read("/drivers/block_s/velocity");
  const std::vector<double> acceleration = file.read("/drivers/block_s/acceleration");
  const std::vector<double> block = file.read("/bodies/block/position");
  ASSERT_EQ(time.size(), 61u);
  ASSERT_EQ(force.size(), time.size());
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double t = time[k];
    // f, f', f'' are the case's own expressions evaluated at t (round-off only).
    EXPECT_NEAR(position[k], rail_position(t), 1e-14);
    EXPECT_NEAR(velocity[k], std::cos(2.0 * t), 1e-14);
    EXPECT_NEAR(acceleration[k], rail_acceleration(t), 1e-14);
    // The block's point on the rail follows f within the projection tolerance (1e-10 m).
    EXPECT_NEAR(Vector3(block[3 * k], block[3 * k + 1], block[3 * k + 2]).dot(rail_direction), rail_position(t), 1e-9);
    EXPECT_NEAR(force[k], block_mass * rail_acceleration(t) + block_mass * g * rail_direction.z(), 1e-10);
  }
}

// A pendulum (CoM at distance l below a pivot about world y, inertia I about its CoM)
// swung by an angle driver from the ground frame to the pendulum's, both turned so that
// their z is world y: theta(t) = 2 t + 0.4 sin(3 t), which passes more than a turn and a
// half in 5 s (the wrapped residual). About the pivot (I + m l^2) theta'' = tau - m g l sin(theta),
// so the driver's torque is tau = (I + m l^2) theta'' + m g l sin(theta).
TEST(DriverKinds, AngleDriverTorqueOnAPendulumIsTheClosedForm) {
  constexpr double m = 1.5, l = 0.8, inertia = 0.02;
  const std::string text =
      "name: swung_pendulum\n"
      "bodies:\n"
      "  - {name: bob, mass: 1.5, center_of_mass: [0, 0, -0.8], inertia: [0.02, 0.02, 0.02]}\n"
      "joints:\n"
      "  - {name: pivot, type: revolute, parent: ground, child: bob, axis: [0, 1, 0]}\n"
      "drivers:\n"
      "  - name: swing\n"
      "    type: angle\n"
      "    body_a: ground\n"
      "    frame_a: {orientation: {axis: [1, 0, 0], angle: -pi/2}}\n"
      "    body_b: bob\n"
      "    frame_b: {orientation: {axis: [1, 0, 0], angle: -pi/2}}\n"
      "    position: 2*t + 0.4*sin(3*t)\n"
      "    velocity: 2 + 1.2*cos(3*t)\n"
      "    acceleration: -3.6*sin(3*t)\n"
      "solver: {integrator: dopri5, rtol: 1e-11, atol: 1e-12, t_end: 5}\n"
      "output: {interval: 0.05}\n";
  H5File file(run_case("angle", text));
  ASSERT_TRUE(file.ok());
  const std::vector<double> time = file.read("/time"), torque = file.read("/drivers/swing/torque");
  const std::vector<double> q = file.read("/joints/pivot/q");
  ASSERT_EQ(time.size(), 101u);
  ASSERT_EQ(torque.size(), time.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double t = time[k], theta = 2 * t + 0.4 * std::sin(3 * t), theta_dd = -3.6 * std::sin(3 * t);
    // The joint angle (not wrapped) follows theta within the projection tolerance.
    EXPECT_NEAR(q[k], theta, 1e-9) << t;
    const double expected = (inertia + m * l * l) * theta_dd + m * g * l * std::sin(theta);
    largest = std::max(largest, std::abs(expected));
    // theta is met to 1e-10 rad, which moves m g l sin(theta) by at most 1.2e-9 N m.
    EXPECT_NEAR(torque[k], expected, 1e-8) << t;
  }
  EXPECT_GT(largest, 10.0);  // the torque swings: the comparison is not of zeros
}

}  // namespace
}  // namespace heavesim::test_driver_kinds
