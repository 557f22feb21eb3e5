// User-defined constraints written as expressions (constraints[i] of type expression):
// a cam/follower in `heavesim kinematics` and in runs with IDA, HHT and Dormand-Prince
// against its closed form, the expression
// "q_a - 2*q_b" against the coupler of ratio 2 over a dynamic run (two constraint kinds
// that must give the same motion and multiplier), and a parabolic guide in `heavesim
// equilibrium` against the minimum of its potential energy, written here; and the
// builder's refusals (unknown joint, quaternion coordinate, two coordinates unnamed).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/case/coordinate_expression.hpp"
#include "kernel/model/model_builder.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

TEST(ExpressionConstraints, CamFollowerKinematicsMatchesTheClosedForm) {
  // cases/kinematics/cam_follower.yaml: s = r sin(theta), theta = omega t.
  constexpr double r = 0.2, omega = 2.0, m = 4.0;
  const std::string output = temporary("cam_follower.h5");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " kinematics " + testing::source_path("cases/kinematics/cam_follower.yaml") +
      " -o " + output);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // nv = 2, one expression row and one driver row: DOF 0.
  EXPECT_NE(result.output.find("rank of the constraint Jacobian 2"), std::string::npos) << result.output;
  const H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<double> time = file.read("/time"), s = file.read("/joints/follower_slide/q"),
                            s_rate = file.read("/joints/follower_slide/qd"),
                            s_acceleration = file.read("/joints/follower_slide/qdd"),
                            lambda = file.read("/constraints/cam_profile/multipliers"),
                            torque = file.read("/drivers/cam_drive/torque");
  ASSERT_EQ(time.size(), 401u);
  ASSERT_EQ(lambda.size(), time.size());
  double position = 0, velocity = 0, acceleration = 0, force = 0, drive = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double theta = omega * time[k];
    position = std::max(position, std::abs(s[k] - r * std::sin(theta)));
    velocity = std::max(velocity, std::abs(s_rate[k] - r * omega * std::cos(theta)));
    acceleration = std::max(acceleration, std::abs(s_acceleration[k] + r * omega * omega * std::sin(theta)));
    // The follower: m s'' = lambda dPhi/ds = lambda. The cam at constant omega: its
    // driver's torque balances lambda dPhi/dtheta = -lambda r cos(theta).
    const double lambda_expected = m * (-r * omega * omega * std::sin(theta));
    force = std::max(force, std::abs(lambda[k] - lambda_expected));
    drive = std::max(drive, std::abs(torque[k] - lambda_expected * r * std::cos(theta)));
  }
  // Newton stops at |Phi| <= 1e-10 by default; the solves of J v = nu and J a = gamma are
  // two 2x2 systems of entries ~1 (round-off ~1e-16 of |s'| = 0.4, |s''| = 0.8).
  EXPECT_LE(position, 1e-10);
  EXPECT_LE(velocity, 1e-10);
  EXPECT_LE(acceleration, 1e-10);
  // The multipliers come from the regularized KKT solve ((S + eps I) lambda = b with
  // eps = 1e-12 max diag S, constrained_dynamics.hpp): a relative bias of eps / sigma_min(S)
  // = 1e-12 x 1.04 / 0.25 ~ 4e-12 (S = J M^-1 J^T with M = diag(1 kg m^2, 4 kg)), i.e.
  // ~1.3e-11 N of |lambda| <= m r omega^2 = 3.2 N and ~3e-12 N m of the torque
  // (|torque| <= 0.32 N m); the bars leave a factor 7 to 8.
  EXPECT_LE(force, 1e-10);
  EXPECT_LE(drive, 2e-11);
  std::filesystem::remove(output);
}

TEST(ExpressionConstraints, CamFollowerRunsOnItsProfileWithIdaHhtAndDopri5) {
  // The same cam in dynamic runs: IDA's GGL index-2 form (J, nu), HHT's index-3 form (Phi,
  // J) and Dormand-Prince with projection (J, gamma, then Phi and nu). Each holds Phi
  // within solver.constraint_tolerance = 1e-10 m, and the driver makes theta exact, so
  // |s - r sin(omega t)| <= 1e-10 m; the multiplier carries the same 4e-12 relative
  // regularization bias as in the kinematic analysis (|lambda| <= 3.2 N).
  constexpr double r = 0.2, omega = 2.0, m = 4.0;
  for (const std::string integrator : {"ida", "hht", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const std::string output = temporary("cam_run_" + integrator + ".h5");
    const testing::CommandResult result = testing::run_command_line(
        testing::heavesim_binary() + " run " + testing::source_path("cases/kinematics/cam_follower.yaml") + " -o " +
        output + " --set solver.integrator=" + integrator + " --set solver.step=0.001");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const H5File file(output);
    ASSERT_TRUE(file.ok());
    const std::vector<double> time = file.read("/time"), s = file.read("/joints/follower_slide/q"),
                              lambda = file.read("/constraints/cam_profile/multipliers");
    ASSERT_EQ(time.size(), 401u);
    double position = 0, force = 0;
    for (std::size_t k = 0; k < time.size(); ++k) {
      position = std::max(position, std::abs(s[k] - r * std::sin(omega * time[k])));
      force = std::max(force, std::abs(lambda[k] + m * r * omega * omega * std::sin(omega * time[k])));
    }
    EXPECT_LE(position, 1e-10);
    EXPECT_LE(force, 1e-10);
    std::filesystem::remove(output);
  }
}

/// Two wheels on vertical axes (gravity along them does no work), wheel a on a torsional
/// spring, geared q_a = 2 q_b by `constraint`.
std::string geared_wheels(const std::string& constraint) {
  return "bodies:\n"
         "  - {name: wheel_a, mass: 1, inertia: {ixx: 0.2, iyy: 0.2, izz: 0.3}}\n"
         "  - {name: wheel_b, mass: 2, inertia: {ixx: 0.4, iyy: 0.4, izz: 0.7}}\n"
         "joints:\n"
         "  - {name: axle_a, type: revolute, parent: ground, child: wheel_a, axis: [0, 0, 1],\n"
         "     spring: {stiffness: 40, damping: 0.3}, initial: {q: 0.4}}\n"
         "  - {name: axle_b, type: revolute, parent: ground, child: wheel_b, axis: [0, 0, 1],\n"
         "     parent_frame: {position: [1, 0, 0]}, initial: {q: 0.2}}\n"
         "constraints:\n  - " +
         constraint +
         "\n"
         "solver: {integrator: dopri5, rtol: 1e-12, atol: 1e-12, t_end: 2}\n"
         "output: {interval: 0.01}\n";
}

TEST(ExpressionConstraints, GearExpressionMovesAsTheCouplerOfRatioTwo) {
  // Phi = q_a - 2 q_b either way: the same row, J = [1, -2], nu = gamma = 0. The
  // expression's derivatives come from Taylor arithmetic on muParser's bytecode, the
  // coupler's from its ratio, so the runs agree to round-off: 1e-12 of the motion's
  // scale (0.4 rad, 40 N m / rad * 0.4 rad = 16 N m).
  std::vector<std::string> outputs;
  for (const std::string& constraint :
       {std::string("{name: gear, type: coupler, joint_a: axle_a, joint_b: axle_b, ratio: 2}"),
        std::string("{name: gear, type: expression, expression: qa - 2*qb, variables: {qa: axle_a, qb: axle_b}}")}) {
    const std::string case_file = temporary("gear_" + std::to_string(outputs.size()) + ".yaml");
    std::ofstream(case_file) << geared_wheels(constraint);
    outputs.push_back(temporary("gear_" + std::to_string(outputs.size()) + ".h5"));
    const testing::CommandResult result =
        testing::run_command_line(testing::heavesim_binary() + " run " + case_file + " -o " + outputs.back());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::filesystem::remove(case_file);
  }
  const H5File coupler(outputs[0]), expression(outputs[1]);
  ASSERT_TRUE(coupler.ok() && expression.ok());
  for (const char* path : {"/joints/axle_a/q", "/joints/axle_b/q", "/joints/axle_b/qd"}) {
    const std::vector<double> a = coupler.read(path), b = expression.read(path);
    ASSERT_EQ(a.size(), 201u) << path;
    ASSERT_EQ(a.size(), b.size()) << path;
    double difference = 0, scale = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      difference = std::max(difference, std::abs(a[k] - b[k]));
      scale = std::max(scale, std::abs(a[k]));
    }
    EXPECT_GT(scale, 0.1) << path;  // it moves
    EXPECT_LE(difference, 1e-12 * scale) << path;
  }
  const std::vector<double> a = coupler.read("/constraints/gear/multipliers"),
                            b = expression.read("/constraints/gear/multipliers");
  ASSERT_EQ(a.size(), b.size());
  double difference = 0, scale = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    difference = std::max(difference, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(a[k]));
  }
  EXPECT_GT(scale, 1.0);
  EXPECT_LE(difference, 1e-12 * scale);
  for (const std::string& output : outputs) std::filesystem::remove(output);
}

TEST(ExpressionConstraints, ParabolicGuideEquilibriumIsTheMinimumOfItsEnergy) {
  // tests/cases/statics_expression_wedge.yaml: x = k x0 / (k + 2 m g a), z = a x^2,
  // lambda = m g (the guide holds the lifter's weight: -m g + lambda dPhi/dz = 0).
  constexpr double k = 2000, x0 = 0.3, m = 10, a = 2, g = 9.81;
  const double x = k * x0 / (k + 2 * m * g * a), z = a * x * x;
  const std::string output = temporary("expression_wedge.h5");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " equilibrium " + testing::source_path("tests/cases/statics_expression_wedge.yaml") +
      " -o " + output);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const H5File file(output);
  ASSERT_TRUE(file.ok());
  // Solved to 1e-13 of the largest load (the spring's ~100 N): a force residual of
  // 1e-11 N over the stiffness k + 2 m g a ~ 2400 N/m moves x by < 1e-14 m; 1e-12
  // leaves room for the last Newton step's differenced stiffness.
  EXPECT_NEAR(file.read("/joints/slide/q")[0], x, 1e-12);
  EXPECT_NEAR(file.read("/joints/lift/q")[0], z, 1e-12);
  // The multiplier comes from the regularized minimum-norm solve (eps = 1e-12 max diag of
  // J M^-1 J^T, constrained_dynamics.hpp): a relative bias of ~1e-12 for this one-row,
  // well-scaled J; 1e-11 leaves a factor 10.
  EXPECT_NEAR(file.read("/constraints/guide/multipliers")[0], m * g, 1e-11 * m * g);
  std::filesystem::remove(output);
}

TEST(ExpressionConstraints, BuilderRefusesQuaternionUnknownAndAmbiguousCoordinates) {
  // ModelError names the variable's key (variables.<symbol>), which to_input_error turns
  // into the case position (the bad cases in tests/bad_cases/expression_*.yaml).
  ModelBuilder builder;
  builder.add_body({"ball", Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_body({"sleeve", Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  JointDefinition joint;
  joint.name = "socket", joint.kind = JointKind::spherical, joint.parent = "ground", joint.child = "ball";
  builder.add_joint(joint);
  joint.name = "shaft", joint.kind = JointKind::cylindrical, joint.parent = "ball", joint.child = "sleeve";
  builder.add_joint(joint);
  const auto function = std::make_shared<const CoordinateExpression>("x - 1", std::vector<std::string>{"x"},
                                                                     std::map<std::string, double>{});
  auto field_of_error = [&](ExpressionVariable variable) {
    ModelBuilder attempt = builder;
    attempt.add_expression_constraint({"rule", {variable}, function});
    try {
      attempt.build();
    } catch (const ModelError& error) {
      return error.field() + ": " + error.found();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field_of_error({"x", "socket", {}}), "variables.x: joint 'socket', a spherical joint");
  EXPECT_EQ(field_of_error({"x", "hinge", {}}), "variables.x: 'hinge', which is not a joint of the tree");
  EXPECT_EQ(field_of_error({"x", "shaft", {}}),
            "variables.x: joint 'shaft', a cylindrical joint with 2 coordinates, without a coordinate");
  EXPECT_EQ(field_of_error({"x", "shaft", 2}), "variables.x.coordinate: 2");
  EXPECT_EQ(field_of_error({"x", "shaft", 1}), "no error");
}

}  // namespace
}  // namespace heavesim
