// Every integrator's numerical failure says when, where and what to try: exit code 3,
// the time, a joint, body or constraint by name, a suggestion, and a readable result
// file marked incomplete (docs/case-format.md, "Numerical failures"). Two failures
// the code did not stage itself: a 1e12 N/m joint spring on a 1 kg slider (stiff
// beyond any explicit step: names joint 'slide') and a loop driven beyond its reach
// at t = 1 s (tests/cases/unreachable_loop.yaml: names the tether, the driver or the
// joint whose speed blows up).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct Failure {
  std::string case_path;
  std::string integrator;
  std::vector<std::string> names;  // one of these must be named, quoted
  double time;                     // s, where the failure is expected (within 5 %)
};

TEST(FailureDiagnosis, EveryIntegratorNamesTimePlaceAndRemedy) {
  const std::vector<Failure> failures = {
      {"tests/cases/unstable_spring.yaml", "ida", {"slide"}, -1.0},
      {"tests/cases/unstable_spring.yaml", "dopri5", {"slide"}, -1.0},
      {"tests/cases/unstable_spring.yaml", "verner6", {"slide"}, -1.0},
      {"tests/cases/unstable_spring.yaml", "fehlberg8", {"slide"}, -1.0},
      {"tests/cases/unstable_spring.yaml", "rk4", {"slide"}, -1.0},
      {"tests/cases/unreachable_loop.yaml", "hht", {"tether", "push", "pin", "rail"}, 1.0},
      {"tests/cases/unreachable_loop.yaml", "ida", {"tether", "push", "pin", "rail"}, 1.0},
      {"tests/cases/unreachable_loop.yaml", "dopri5", {"tether", "push", "pin", "rail"}, 1.0},
      {"tests/cases/unreachable_loop.yaml", "verner6", {"tether", "push", "pin", "rail"}, 1.0},
      {"tests/cases/unreachable_loop.yaml", "fehlberg8", {"tether", "push", "pin", "rail"}, 1.0},
      {"tests/cases/unreachable_loop.yaml", "rk4", {"tether", "push", "pin", "rail"}, 1.0},
  };
  const std::regex failure_time(R"(numerical failure in case '[^']+' at t = ([0-9.e+-]+) s)");
  for (const Failure& failure : failures) {
    const std::string label = failure.case_path + " with " + failure.integrator;
    const std::string output =
        (std::filesystem::temp_directory_path() / ("heavesim_failure_" + failure.integrator + ".h5")).string();
    const testing::CommandResult result = testing::run_case(
        failure.case_path, output, "-q --set solver.integrator=" + failure.integrator + " --set solver.step=1e-3");
    EXPECT_EQ(result.exit_code, 3) << label << ": " << result.output;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(result.output, match, failure_time)) << label << ": " << result.output;
    if (failure.time > 0.0) {
      EXPECT_NEAR(std::stod(match[1]), failure.time, 0.05 * failure.time) << label;
    }
    bool named = false;
    for (const std::string& name : failure.names) named |= result.output.find("'" + name + "'") != std::string::npos;
    EXPECT_TRUE(named) << label << " names none of the expected joints, bodies or constraints: " << result.output;
    EXPECT_NE(result.output.find("suggestion: "), std::string::npos) << label << ": " << result.output;
    EXPECT_EQ(result.output.find("nan"), std::string::npos) << label << ": " << result.output;
    H5File file(output);
    ASSERT_TRUE(file.ok()) << label;
    EXPECT_EQ(file.long_attribute("/", "complete"), 0) << label;
    std::filesystem::remove(output);
  }
}

}  // namespace
}  // namespace heavesim
