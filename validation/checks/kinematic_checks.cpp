// Kinematic analysis (heavesim kinematics, app/run/kinematic_run.hpp) against closed
// forms written in validation/oracles/mechanism_kinematics.hpp:
//   L3  the MKSim seed's slider-crank, block driven x = 8 + 3 sin t: crank angle, speed and
//       acceleration against cos(theta) = (x^2 + r^2 - l^2) / (2 r x) and its exact
//       derivatives; the rod's idle spin (the one free direction) held at zero;
//   L6  a Grashof crank-rocker four-bar through a full crank turn against the
//       loop-closure solution (triangle geometry, Cramer for rates);
//   L7  the same four-bar's DOF report: 3 redundant equations, named;
//   L8  the torque that drives a slider-crank's crank against Lagrange's equation.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/run/kinematic_run.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/mechanism_kinematics.hpp"

namespace heavesim::validation {

KinematicOutcome run_kinematic_case(const std::string& relative_path, const std::vector<std::string>& overrides,
                                    const std::function<void(double t, const MultibodySystem& system)>& sample) {
  const CaseDefinition definition = load_case(project_file(relative_path), overrides);
  Scene scene = build_scene(definition);
  return run_kinematics(scene, definition, true, [&](double t, const VectorX&, const KinematicPoint&) {
    sample(t, *scene.system);
    return true;
  });
}

namespace {

constexpr const char* slider_crank_case = "cases/kinematics/mksim_slider_crank.yaml";
constexpr const char* four_bar_case = "cases/kinematics/grashof_four_bar.yaml";
constexpr const char* driven_crank_case = "cases/kinematics/driven_slider_crank.yaml";

/// Coordinate 0 of joint `name`: q, qd, qdd of the system's last evaluation.
oracle::Motion3 joint_motion(const MultibodySystem& system, const std::string& name) {
  const Joint& joint = system.model().joints[system.model().joint_index(name)];
  return {system.configuration()[joint.q_index], system.velocity()[joint.v_index], system.data().qdd[joint.v_index]};
}

/// Angle difference wrapped into (-pi, pi].
double angle_error(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }

}  // namespace

std::vector<ValidationRow> check_l3_mksim_slider_crank() {
  const double r = 3.5, l = 8.0;
  double position = 0.0, velocity = 0.0, acceleration = 0.0, spin = 0.0, block = 0.0;
  const KinematicOutcome outcome = run_kinematic_case(slider_crank_case, {}, [&](double t, const MultibodySystem& system) {
    const oracle::Motion3 x{8 + 3 * std::sin(t), 3 * std::cos(t), -3 * std::sin(t)};
    const oracle::Motion3 theta = oracle::slider_crank_crank_angle(r, l, x);
    const oracle::Motion3 crank = joint_motion(system, "crank_pivot");
    position = std::max(position, angle_error(crank.position, theta.position));
    velocity = std::max(velocity, std::abs(crank.velocity - theta.velocity));
    acceleration = std::max(acceleration, std::abs(crank.acceleration - theta.acceleration));
    const oracle::Motion3 slide = joint_motion(system, "slide");
    block = std::max({block, std::abs(slide.position - x.position), std::abs(slide.velocity - x.velocity),
                      std::abs(slide.acceleration - x.acceleration)});
    // The rod's spin about its own axis (world x-y plane, rod direction) relative to what
    // the crank and block impose: its angular velocity along the rod.
    const Model& model = system.model();
    const int rod = model.link_index("rod");
    const Vector3 axis = system.data().X_world_link[rod].rotation().col(0);
    spin = std::max(spin, std::abs(system.data().velocity_world[rod].angular().dot(axis)));
  });
  const std::string subject = outcome.completed
                                  ? fmt::format("L3 MKSim slider-crank r = 3.5, l = 8, x = 8 + 3 sin t, {} points",
                                                outcome.points)
                                  : "L3 MKSim slider-crank: stopped";
  const double failed = outcome.completed ? 0.0 : INFINITY;
  return {{"L3", subject, "crank angle vs acos((x^2 + r^2 - l^2)/(2 r x)) [rad]", position + failed, 1e-12},
          {"L3", subject, "crank speed vs its exact derivative [rad/s]", velocity + failed, 1e-12},
          {"L3", subject, "crank acceleration vs its exact derivative [rad/s^2]", acceleration + failed, 1e-12},
          {"L3", subject, "block x, x', x'' vs the driver [m, m/s, m/s^2]", block + failed, 1e-12},
          {"L3", subject, "rod spin about its axis (free direction, minimum-energy motion) [rad/s]", spin + failed,
           1e-12}};
}

std::vector<ValidationRow> check_l6_grashof_four_bar() {
  const double a = 1, b = 4, c = 3, d = 4;
  double position = 0.0, velocity = 0.0, acceleration = 0.0, turned = 0.0;
  const KinematicOutcome outcome = run_kinematic_case(four_bar_case, {}, [&](double, const MultibodySystem& system) {
    const oracle::Motion3 crank = joint_motion(system, "crank_pivot");
    const oracle::Motion3 coupler_relative = joint_motion(system, "coupler_pin");
    const oracle::Motion3 rocker = joint_motion(system, "rocker_pivot");
    const oracle::FourBarAngles exact = oracle::four_bar_angles(a, b, c, d, crank, -1);
    const oracle::Motion3 coupler{crank.position + coupler_relative.position, crank.velocity + coupler_relative.velocity,
                                  crank.acceleration + coupler_relative.acceleration};
    position = std::max({position, angle_error(coupler.position, exact.coupler.position),
                         angle_error(rocker.position, exact.rocker.position)});
    velocity = std::max({velocity, std::abs(coupler.velocity - exact.coupler.velocity),
                         std::abs(rocker.velocity - exact.rocker.velocity)});
    acceleration = std::max({acceleration, std::abs(coupler.acceleration - exact.coupler.acceleration),
                             std::abs(rocker.acceleration - exact.rocker.acceleration)});
    turned = crank.position;
  });
  const std::string subject =
      outcome.completed ? fmt::format("L6 Grashof crank-rocker (1, 4, 3, 4 m), crank through {:.4f} rad, {} points",
                                      turned, outcome.points)
                        : "L6 Grashof crank-rocker: stopped";
  const double failed = outcome.completed && turned >= 2 * M_PI ? 0.0 : INFINITY;
  return {{"L6", subject, "coupler and rocker angles vs loop closure [rad]", position + failed, 1e-10},
          {"L6", subject, "their speeds [rad/s]", velocity + failed, 1e-10},
          {"L6", subject, "their accelerations [rad/s^2]", acceleration + failed, 1e-10}};
}

std::vector<ValidationRow> check_l7_redundant_four_bar() {
  std::vector<ValidationRow> rows =
      assembly_structure_rows("L7", "L7 planar four-bar of 3-D revolutes", four_bar_case, 3, 0);
  // The redundant rows by name: the loop joint's out-of-plane equations, in its frame
  // (axis z): translation along z and rotations about x and y.
  const Scene scene = build_scene(load_case(project_file(four_bar_case)));
  const std::string named = describe_redundant_rows(*scene.model, scene.assembly.rank);
  int missing = 0;
  for (const char* row : {"translation along z", "rotation about x", "rotation about y"})
    missing += named.find(row) == std::string::npos ? 1 : 0;
  missing += named.find("loop joint 'rocker_pin'") == std::string::npos ? 1 : 0;
  rows.push_back({"L7", "L7 redundant equations named: " + named,
                  "out-of-plane rows of loop joint 'rocker_pin' not named (count)", static_cast<double>(missing), 0.0});
  return rows;
}

std::vector<ValidationRow> check_l8_driving_torque() {
  const double r = 1, l = 3, crank_inertia = 2, block_mass = 3;
  double torque_error = 0.0, torque_scale = 0.0, block_error = 0.0;
  const KinematicOutcome outcome = run_kinematic_case(driven_crank_case, {}, [&](double t, const MultibodySystem& system) {
    const oracle::Motion3 theta{3 * t + std::sin(2 * t), 3 + 2 * std::cos(2 * t), -4 * std::sin(2 * t)};
    const oracle::DrivenSliderCrank exact = oracle::driven_slider_crank(r, l, crank_inertia, block_mass, theta);
    const Model& model = system.model();
    const auto driver = std::find_if(model.constraints.begin(), model.constraints.end(),
                                     [](const Constraint& constraint) { return constraint.name == "crank_drive"; });
    const double torque = system.data().constraint_multipliers[driver->first_row];
    torque_error = std::max(torque_error, std::abs(torque - exact.torque));
    torque_scale = std::max(torque_scale, std::abs(exact.torque));
    const Vector3 block = system.data().X_world_link[model.link_index("block")].translation();
    block_error = std::max(block_error, std::abs(block.x() - exact.x));
  });
  const std::string subject = outcome.completed
                                  ? fmt::format("L8 driven slider-crank (r = 1, l = 3 m, I = 2 kg m^2, m = 3 kg), "
                                                "theta = 3t + sin 2t, {} points, peak torque {:.4g} N m",
                                                outcome.points, torque_scale)
                                  : "L8 driven slider-crank: stopped";
  const double failed = outcome.completed ? 0.0 : INFINITY;
  return {{"L8", subject, "driver torque vs Lagrange, relative to its peak", torque_error / torque_scale + failed, 1e-9},
          {"L8", subject, "block x vs r cos + sqrt(l^2 - r^2 sin^2) [m]", block_error + failed, 1e-12}};
}

}  // namespace heavesim::validation
