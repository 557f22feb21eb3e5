// heavesim kinematics (app/run/kinematic_run.hpp, cli/commands/kinematics_command.cpp) and
// the kernel's kinematic solves (kernel/analysis/kinematic_analysis.hpp): the command end
// to end against the slider-crank's closed form, the minimum-norm solves against a
// pseudo-inverse written here, branch continuity at large steps, and the failures
// (unreachable position: exit 3; over-driven: exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <Eigen/QR>

#include "app/case/case_definition.hpp"
#include "app/run/kinematic_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

constexpr const char* slider_crank = "cases/kinematics/mksim_slider_crank.yaml";
constexpr const char* four_bar = "cases/kinematics/grashof_four_bar.yaml";

/// The crank angle of the MKSim slider-crank (r = 3.5, l = 8) for the block at x, on
/// the branch with the crank pin above the line: the law of cosines.
double crank_angle(double x) { return std::acos((x * x + 3.5 * 3.5 - 8.0 * 8.0) / (2 * 3.5 * x)); }

std::string kinematics_command_line(const std::string& case_file, const std::string& output, const std::string& extra = "") {
  return testing::heavesim_binary() + " kinematics " + testing::source_path(case_file) + " -o " + output + " " + extra;
}

TEST(KinematicsCommand, SliderCrankReportsItsFreedomAndWritesTheExactMotion) {
  const std::string output = temporary("kinematics_slider_crank.h5");
  const testing::CommandResult result = testing::run_command_line(kinematics_command_line(slider_crank, output));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // nv = 1 (crank) + 3 (ball) + 1 (slide); rows = 3 (ball loop) + 1 (driver).
  EXPECT_NE(result.output.find("5 joint coordinates, 4 constraint equations (1 from drivers): Gruebler count 1"),
            std::string::npos) << result.output;
  EXPECT_NE(result.output.find("rank of the constraint Jacobian 4, so 1 free direction"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("free direction 1: joint 'crank_ball'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("driver 'block_x': peak driving force"), std::string::npos) << result.output;

  const H5File file(output);
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.string_attribute("/", "analysis"), "kinematics");
  EXPECT_EQ(file.long_attribute("/", "complete"), 1);
  EXPECT_EQ(file.long_attribute("/", "dof"), 1);
  EXPECT_EQ(file.long_attribute("/", "rank"), 4);
  EXPECT_EQ(file.long_attribute("/", "grubler_dof"), 1);
  const std::vector<double> time = file.read("/time"), crank = file.read("/joints/crank_pivot/q");
  const std::vector<double> iterations = file.read("/kinematics/newton_iterations");
  const std::vector<double> residual = file.read("/kinematics/equation_residual");
  ASSERT_EQ(time.size(), 1001u);
  ASSERT_EQ(crank.size(), time.size());
  ASSERT_EQ(iterations.size(), time.size());
  double error = 0.0, most_iterations = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    error = std::max(error, std::abs(crank[k] - crank_angle(8 + 3 * std::sin(time[k]))));
    most_iterations = std::max(most_iterations, iterations[k]);
    EXPECT_LE(residual[k], 1e-12);
  }
  // acos loses digits only near 0 and pi; the crank stays within [0.3, 2] rad.
  EXPECT_LE(error, 1e-12);
  // The predictor's O(h^3) guess: a couple of Newton steps per point at h = 0.01 s.
  EXPECT_LE(most_iterations, 4.0);
  std::filesystem::remove(output);
}

TEST(KinematicsCommand, UnreachablePositionStopsWithExit3NamingTheDriverAndKeepsTheFile) {
  // x = 8 + 5 sin t passes the reach r + l = 11.5 m at sin t = 0.7, t = 0.775 s.
  const std::string output = temporary("kinematics_unreachable.h5");
  const testing::CommandResult result = testing::run_command_line(kinematics_command_line(
      slider_crank, output,
      "--set 'drivers[block_x].position=8 + 5*sin(t)' --set 'drivers[block_x].velocity=5*cos(t)' "
      "--set 'drivers[block_x].acceleration=-5*sin(t)'"));
  EXPECT_EQ(result.exit_code, 3) << result.output;
  EXPECT_NE(result.output.find("cannot be reached"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("driver 'block_x'"), std::string::npos) << result.output;
  const H5File file(output);
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.long_attribute("/", "complete"), 0);
  const double failure_time = file.double_attribute("/", "failure_time");
  EXPECT_GT(failure_time, 0.75);
  EXPECT_LT(failure_time, 0.80);
  EXPECT_GE(file.long_attribute("/", "samples_written"), 70);
  std::filesystem::remove(output);
}

/// The case's scene at its assembled state, with the position stage current.
struct AssembledCase {
  explicit AssembledCase(const std::string& path, const std::vector<std::string>& overrides = {})
      : definition(load_case(testing::source_path(path), overrides)), scene(build_scene(definition)) {}
  CaseDefinition definition;
  Scene scene;
};

TEST(KinematicAnalysis, MinimumNormSolvesMatchTheWeightedPseudoInverse) {
  // The four-bar's J has 3 zero (redundant) rows: J M^-1 J^T is singular. The reference is
  // Eigen's complete orthogonal decomposition (a different factorization from the
  // solver's pivoted QR): v = W^-1 J^T (J W^-1 J^T)^+ nu, for W = M and W = I.
  for (const MotionWeighting weighting : {MotionWeighting::mass, MotionWeighting::unit}) {
    AssembledCase setup(four_bar);
    const Model& model = *setup.scene.model;
    Data& data = setup.scene.system->mutable_data();
    KinematicSettings settings;
    settings.weighting = weighting;
    KinematicWorkspace workspace(model);
    const double t = 0.37;
    VectorX q = setup.scene.initial_state.head(model.nq), v = VectorX::Zero(model.nv), a = VectorX::Zero(model.nv);
    const KinematicPoint point = solve_positions(model, data, workspace, settings, t, q);
    ASSERT_TRUE(point.converged);
    EXPECT_EQ(point.rank, 3);
    solve_velocities_and_accelerations(model, data, workspace, t, q, v, a);

    update_positions(model, data, q);
    MatrixX J(model.num_constraint_rows, model.nv);
    constraint_jacobian(model, data, t, J);
    const MatrixX W = weighting == MotionWeighting::mass ? MatrixX(mass_matrix(model, data))
                                                         : MatrixX::Identity(model.nv, model.nv);
    const MatrixX W_inverse_Jt = W.llt().solve(J.transpose());
    const MatrixX schur = J * W_inverse_Jt;
    Eigen::CompleteOrthogonalDecomposition<MatrixX> pseudo(schur);
    pseudo.setThreshold(1e-12);
    VectorX nu(model.num_constraint_rows), gamma(model.num_constraint_rows);
    constraint_velocity_target(model, data, t, nu);
    const VectorX v_reference = W_inverse_Jt * pseudo.solve(nu);
    update_velocities(model, data, q, v_reference);
    constraint_bias(model, data, t, gamma);
    const VectorX a_reference = W_inverse_Jt * pseudo.solve(gamma);
    // Round-off of two factorizations of a matrix with entries ~ 1-40 (m, kg m^2).
    EXPECT_LE((v - v_reference).cwiseAbs().maxCoeff(), 1e-12 * v_reference.cwiseAbs().maxCoeff());
    EXPECT_LE((a - a_reference).cwiseAbs().maxCoeff(), 1e-11 * a_reference.cwiseAbs().maxCoeff());
    // Both satisfy the constraints exactly.
    EXPECT_LE((J * v - nu).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(KinematicAnalysis, LargeStepsStayOnTheAssemblyBranch) {
  // Output intervals 50 times the cases' own: the crank turns up to ~0.6 rad (slider-crank,
  // 0.5 s) and ~0.5 rad (four-bar, 0.05 s... the crank's speed peaks at 2.6 pi rad/s)
  // between points; the second-order predictor keeps the solution on the branch it
  // started on (pin above the line; four-bar uncrossed), which the closed forms name.
  {
    AssembledCase setup(slider_crank, {"output.interval=0.5"});
    const Model& model = *setup.scene.model;
    const int crank = model.joints[model.joint_index("crank_pivot")].q_index;
    double error = 0.0;
    const KinematicOutcome outcome = run_kinematics(setup.scene, setup.definition, false,
                                                    [&](double t, const VectorX& y, const KinematicPoint&) {
      error = std::max(error, std::abs(y[crank] - crank_angle(8 + 3 * std::sin(t))));
      return true;
    });
    EXPECT_TRUE(outcome.completed);
    EXPECT_EQ(outcome.points, 21);
    EXPECT_LE(error, 1e-12);
  }
  {
    AssembledCase setup(four_bar, {"output.interval=0.05"});
    const Model& model = *setup.scene.model;
    const int rocker = model.joints[model.joint_index("rocker_pivot")].q_index;
    const int crank = model.joints[model.joint_index("crank_pivot")].q_index;
    // Uncrossed branch: the rocker pin B above the line O4-A, i.e. (A - O4) x (B - O4) < 0.
    int crossed = 0;
    const KinematicOutcome outcome = run_kinematics(setup.scene, setup.definition, false,
                                                    [&](double, const VectorX& y, const KinematicPoint&) {
      const double ax = std::cos(y[crank]) - 4, ay = std::sin(y[crank]);
      const double bx = 3 * std::cos(y[rocker]), by = 3 * std::sin(y[rocker]);
      crossed += ax * by - ay * bx < 0 ? 0 : 1;
      return true;
    });
    EXPECT_TRUE(outcome.completed);
    EXPECT_EQ(crossed, 0);
  }
}

TEST(KinematicsCommand, OverDrivenMechanismIsBadInputAtTheDriver) {
  // The four-bar has one degree of freedom, which its crank driver takes; a second driver
  // holding the rocker at 2 rad (where the crank puts it at 1.68 rad) asks for what the
  // loop and the crank already fix. Appended by name through an include.
  const std::string path = temporary("over_driven.yaml");
  {
    std::ofstream text(path);
    text << "include: " << testing::source_path(four_bar) << "\n"
         << "drivers:\n"
         << "  - name: rocker_hold\n"
         << "    joint: rocker_pivot\n"
         << "    position: 2 + 0*t\n";
  }
  const std::string output = temporary("over_driven.h5");
  const testing::CommandResult result =
      testing::run_command_line(testing::heavesim_binary() + " kinematics " + path + " -o " + output);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  // At the second driver's name (drivers[1], line 3 of the file above), naming what it fights.
  EXPECT_NE(result.output.find(path + ":3:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("drivers[1]"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("over-driven mechanism: driver 'rocker_hold'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("driver 'crank_turn'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("loop joint 'rocker_pin'"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(output));
  std::filesystem::remove(path);
}

TEST(KinematicsCommand, DeadCentresAreReportedWithTheTimeAndTheDriver) {
  // r = 3, l = 8: the stroke x = 8 + 3 sin t in [5, 11] = [l - r, l + r] ends on both dead
  // centres (crank and rod aligned) at t = pi/2 and 3 pi/2; the samples pass 0.8 ms from
  // them, where the rank-4 singular value falls to ~4e-4 of the largest.
  const std::string output = temporary("kinematics_dead_centres.h5");
  const testing::CommandResult result = testing::run_command_line(kinematics_command_line(
      slider_crank, output, "--set parameters.r=3 --set kinematics.singular_ratio=1e-3"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("singular configuration at t = 1.57 s"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("singular configuration at t = 4.71 s"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("driver 'block_x'"), std::string::npos) << result.output;
  const H5File file(output);
  const std::vector<double> ratio = file.read("/kinematics/smallest_singular_ratio");
  EXPECT_LT(*std::min_element(ratio.begin(), ratio.end()), 1e-3);
  std::filesystem::remove(output);
}

TEST(KinematicsCommand, SettingsOutsideTheirRangeAreBadInputAtTheirKey) {
  for (const auto& [setting, key] : std::vector<std::pair<std::string, std::string>>{
           {"kinematics.weighting=heavy", "kinematics.weighting"},
           {"kinematics.equation_tolerance=1e-16", "kinematics.equation_tolerance"},
           {"kinematics.max_iterations=0", "kinematics.max_iterations"},
           {"kinematics.singular_ratio=2", "kinematics.singular_ratio"},
           {"kinematics.newton=3", "kinematics.newton"}}) {
    const testing::CommandResult result = testing::run_command_line(
        kinematics_command_line(slider_crank, temporary("never_written.h5"), "--set " + setting));
    EXPECT_EQ(result.exit_code, 2) << setting << "\n" << result.output;
    EXPECT_NE(result.output.find(key), std::string::npos) << setting << "\n" << result.output;
  }
}

}  // namespace
}  // namespace heavesim
