// The checks a driver's expressions pass before a run: explicit derivatives must be the
// exact derivatives of the position to within round-off (1e-9 of their scale over the
// run, a true value of 0 included), and every expression of t must be finite over the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/test_support.hpp"

namespace heavesim {
namespace {

/// A crank on a revolute joint driven by `driver` (the lines under `- name: motor`).
std::string write_driven_case(const std::string& file_name, const std::string& driver, const std::string& solver) {
  const std::string path = (std::filesystem::temp_directory_path() / file_name).string();
  std::ofstream(path) << "bodies:\n"
                         "  - {name: crank, mass: 1, inertia: [0.1, 0.1, 0.1]}\n"
                         "joints:\n"
                         "  - {name: pivot, type: revolute, parent: ground, child: crank, axis: [0, 0, 1]}\n"
                         "drivers:\n"
                         "  - name: motor\n"
                         "    joint: pivot\n"
                      << driver << "solver: " << solver << "\n";
  return path;
}

testing::CommandResult check(const std::string& path) {
  return testing::run_command_line(testing::heavesim_binary() + " check " + path);
}

TEST(DriverChecks, LinearMotionWithExactDerivativesIsAcceptedAndRuns) {
  // The issue's case: acceleration 0 was refused ("differs from d2(position)/dt2 by
  // 1.13e-08"), the tolerance having collapsed with the true value 0.
  const std::string path = write_driven_case("heavesim_driver_linear.yaml",
                                             "    position: 2 + 0.5*t\n    velocity: 0.5\n    acceleration: 0\n",
                                             "{t_end: 2}");
  const testing::CommandResult checked = check(path);
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  const std::string output = (std::filesystem::temp_directory_path() / "heavesim_driver_linear.h5").string();
  const testing::CommandResult ran =
      testing::run_command_line(testing::heavesim_binary() + " run " + path + " -q -o " + output);
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
}

TEST(DriverChecks, LinearMotionLateInALongRunIsAccepted) {
  // At t = 1000 s the rounding of t itself (eps t v) dominates the differences' error:
  // refused before ("differs from d2(position)/dt2 by 1.14e-06 at t = 1000.35 s").
  const std::string path = write_driven_case("heavesim_driver_linear_late.yaml",
                                             "    position: 2 + 7*(t - 1000)\n    velocity: 7\n    acceleration: 0\n",
                                             "{t_start: 1000, t_end: 1007}");
  const testing::CommandResult checked = check(path);
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
}

TEST(DriverChecks, OscillationWithExactDerivativesIsAccepted) {
  const std::string path = write_driven_case(
      "heavesim_driver_sine.yaml",
      "    position: 5 + 0.3*sin(2*t)\n    velocity: 0.6*cos(2*t)\n    acceleration: -1.2*sin(2*t)\n", "{t_end: 20}");
  EXPECT_EQ(check(path).exit_code, 0);
}

TEST(DriverChecks, WrongDerivativesOfALinearMotionAreRefused) {
  struct Wrong {
    std::string derivatives, key, difference;
  };
  for (const Wrong& wrong : {Wrong{"    velocity: 0.6\n    acceleration: 0\n", "drivers[0].velocity", "by 0.1 "},
                             Wrong{"    velocity: 0.5\n    acceleration: 1\n", "drivers[0].acceleration", "by 1 "},
                             Wrong{"    velocity: 0.5\n    acceleration: 1e-3\n", "drivers[0].acceleration",
                                   "by 0.001 "}}) {
    SCOPED_TRACE(wrong.derivatives);
    const std::string path = write_driven_case("heavesim_driver_wrong.yaml",
                                               "    position: 2 + 0.5*t\n" + wrong.derivatives, "{t_end: 2}");
    const testing::CommandResult checked = check(path);
    EXPECT_EQ(checked.exit_code, 2) << checked.output;
    EXPECT_NE(checked.output.find(": " + wrong.key + ": found "), std::string::npos) << checked.output;
    EXPECT_NE(checked.output.find(wrong.difference), std::string::npos) << checked.output;
  }
}

TEST(DriverChecks, ExpressionNotFiniteInsideTheRunIsBadInputAtItsKeyNotANumericalFailure) {
  // sqrt(1 - t) on a 2 s run: was "numerical failure at t = 0 s" (exit 3) without its key.
  const std::string path =
      write_driven_case("heavesim_driver_sqrt.yaml", "    position: sqrt(1 - t)\n", "{t_end: 2}");
  const testing::CommandResult checked = check(path);
  EXPECT_EQ(checked.exit_code, 2) << checked.output;
  EXPECT_NE(checked.output.find(path + ":8:"), std::string::npos) << checked.output;
  EXPECT_NE(checked.output.find(": drivers[0].position: found driver 'motor': the expression 'sqrt(1 - t)"),
            std::string::npos)
      << checked.output;
  EXPECT_NE(checked.output.find("is not finite at t = 1"), std::string::npos) << checked.output;
}

TEST(DriverChecks, ExpressionFiniteOverTheRunIsAcceptedThoughNotBeyond) {
  // sqrt(3 - t) has no value after 3 s; a 2 s run with exact derivatives never reads it there.
  const std::string path = write_driven_case(
      "heavesim_driver_sqrt_inside.yaml",
      "    position: sqrt(3 - t)\n    velocity: -0.5/sqrt(3 - t)\n    acceleration: -0.25/(3 - t)^1.5\n",
      "{t_end: 2}");
  const testing::CommandResult checked = check(path);
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
}

}  // namespace
}  // namespace heavesim
