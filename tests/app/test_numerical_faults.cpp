// Numerical failures blame the part that causes them (issue #13, class 9): every fault
// case in tests/cases/fault_*.yaml runs to exit 3 at a stated time, names the joint,
// body, element or constraint as the case wrote it, suggests what fits the cause, and
// leaves a readable result file marked complete = 0. The expected frequencies and
// stability limits are closed forms (stated with each case), not the code's output.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct Fault {
  std::string case_path;
  std::string settings;                  // extra command-line settings (--set ...)
  double earliest, latest;               // s: the failure time must lie in [earliest, latest]
  std::vector<std::string> names;        // each must appear quoted: 'name'
  std::vector<std::string> phrases;      // each must appear in the message or the suggestion
  std::vector<std::string> not_suggested;  // none may appear in the suggestion (a wrong remedy)
};

/// Runs the fault and checks the contract; returns the message (what and suggestion).
std::string expect_fault(const Fault& fault) {
  const std::string label = fault.case_path + " " + fault.settings;
  const std::string output = (std::filesystem::temp_directory_path() /
                              ("heavesim_fault_" + std::filesystem::path(fault.case_path).stem().string() + ".h5"))
                                 .string();
  const testing::CommandResult result = testing::run_case(fault.case_path, output, "-q " + fault.settings);
  EXPECT_EQ(result.exit_code, 3) << label << ": " << result.output;
  std::smatch match;
  const std::regex failure(R"(numerical failure in case '[^']+' at t = ([0-9.e+-]+) s: ([^\n]*)\n  suggestion: ([^\n]*))");
  if (!std::regex_search(result.output, match, failure)) {
    ADD_FAILURE() << label << ": no numerical-failure report in: " << result.output;
    return "";
  }
  const double time = std::stod(match[1]);
  const std::string what = match[2], suggestion = match[3];
  EXPECT_GE(time, fault.earliest) << label;
  EXPECT_LE(time, fault.latest) << label;
  for (const std::string& name : fault.names)
    EXPECT_NE(what.find("'" + name + "'"), std::string::npos) << label << " does not name '" << name << "': " << what;
  for (const std::string& phrase : fault.phrases)
    EXPECT_NE((what + " " + suggestion).find(phrase), std::string::npos)
        << label << " does not say \"" << phrase << "\": " << what << "\n  suggestion: " << suggestion;
  for (const std::string& phrase : fault.not_suggested)
    EXPECT_EQ(suggestion.find(phrase), std::string::npos) << label << " suggests \"" << phrase << "\": " << suggestion;
  // Components by name, never by index ("velocity coordinate 1", "component 7").
  EXPECT_FALSE(std::regex_search(what, std::regex(R"((coordinate|component) [0-9])"))) << label << ": " << what;
  EXPECT_EQ(what.find("nan"), std::string::npos) << label << ": " << what;
  H5File file(output);
  EXPECT_TRUE(file.ok()) << label;
  if (file.ok()) {
    EXPECT_EQ(file.long_attribute("/", "complete"), 0) << label;
    EXPECT_NEAR(file.double_attribute("/", "failure_time"), time, 1e-6 * (1.0 + time)) << label;
  }
  std::filesystem::remove(output);
  return what + "\n" + suggestion;
}

/// The number printed after `prefix` in `text` (NaN if absent).
double number_after(const std::string& text, const std::string& prefix) {
  const std::size_t at = text.find(prefix);
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + prefix.size()));
}

constexpr double rk4_imaginary_limit = 2.8284271247461903;  // |h lambda| on the imaginary axis: sqrt(8)
constexpr double rk4_real_limit = 2.785293563405282;        // on the negative real axis

TEST(NumericalFaults, StiffStrutUnderRk4BlamesTheStepNotTheGasVolume) {
  // omega = sqrt(k (1/m_load + 1/m_platform)) = sqrt(1e15 (1/2.9e5 + 1/1e6)) = 6.67e4 rad/s.
  const std::string message = expect_fault({"tests/cases/fault_stiff_strut_rk4.yaml", "", 0.05, 0.05,
                                            {"strut", "load"},
                                            {"beyond rk4's stability limit", "solver.step <=", "hht", "ida"},
                                            {"end stop", "gas"}});
  const double omega = std::sqrt(1e15 * (1.0 / 2.9e5 + 1.0 / 1e6));
  EXPECT_NEAR(number_after(message, "omega = "), omega, 0.01 * omega) << message;
  EXPECT_NEAR(number_after(message, "stability limit of "), rk4_imaginary_limit / omega, 0.01 * rk4_imaginary_limit / omega)
      << message;
}

TEST(NumericalFaults, StiffDamperUnderRk4NamesTheDamperAndItsDecayRate) {
  // c / m = 1e6 / 10 = 1e5 1/s; RK4's limit 2.785 / 1e5 s.
  const std::string message = expect_fault({"tests/cases/fault_stiff_damper_rk4.yaml", "", 0.0, 0.2,
                                            {"dashpot", "block"},
                                            {"decay rate 1e+05 1/s", "solver.step <="},
                                            {}});
  EXPECT_NEAR(number_after(message, "stability limit of "), rk4_real_limit / 1e5, 0.01 * rk4_real_limit / 1e5) << message;
}

TEST(NumericalFaults, StiffJointSpringUnderEveryAdaptiveExplicitMethodNamesTheSpring) {
  // omega = sqrt(1e12 / 1) = 1e6 rad/s; 2000 steps cannot cover a 0.1 s interval at the
  // stability limit (a few microseconds): it fails within the first interval.
  for (const std::string method : {"dopri5", "verner6", "fehlberg8"})
    expect_fault({"tests/cases/fault_stiff_joint_spring_erk.yaml", "--set solver.integrator=" + method, 0.0, 0.1,
                  {"slide", "slider"},
                  {"omega = 1e+06 rad/s", "the spring of joint 'slide'", "solver.max_steps = 2000", "hht",
                   "solver.max_steps above"},
                  {}});
}

TEST(NumericalFaults, StiffJointSpringUnderIdaSaysItResolvesTheOscillation) {
  expect_fault({"tests/cases/fault_stiff_joint_spring_ida.yaml", "", 0.0, 0.1,
                {"slide", "slider"},
                {"omega = 1e+06 rad/s", "the spring of joint 'slide'", "hht", "solver.max_steps above"},
                {}});
}

TEST(NumericalFaults, TinyMassIsNamedWhereverItSitsInTheChain) {
  // The light cart oscillates between its neighbours' springs: omega = sqrt((k_in +
  // k_out) / m) = sqrt(200 / 1e-6) for carts 1 and 2, sqrt(100 / 1e-6) for the last.
  const double omegas[] = {std::sqrt(200.0 / 1e-6), std::sqrt(200.0 / 1e-6), std::sqrt(100.0 / 1e-6)};
  for (int k = 1; k <= 3; ++k) {
    const std::string cart = "cart" + std::to_string(k), slide = "slide" + std::to_string(k);
    const std::string message = expect_fault({"tests/cases/fault_tiny_mass_chain.yaml",
                                              "--set parameters.m" + std::to_string(k) + "=1e-6", 0.0, 1.0,
                                              {cart},
                                              {"moves body '" + cart + "' (1e-06 kg, joint '" + slide + "')",
                                               "the spring of joint '" + slide + "'", "solver.step <="},
                                              {}});
    EXPECT_NEAR(number_after(message, "omega = "), omegas[k - 1], 0.01 * omegas[k - 1]) << cart << ": " << message;
  }
}

TEST(NumericalFaults, DriverBeyondTheLoopsReachIsNamedByEveryIntegrator) {
  // x = 1 + 3 t reaches the loop's reach, 2 m, at t = 1/3 s.
  for (const std::string method : {"ida", "hht", "rk4", "dopri5"})
    expect_fault({"tests/cases/fault_driver_beyond_reach.yaml", "--set solver.integrator=" + method, 0.32, 1.0 / 3.0 + 1e-3,
                  {"push", "tether"},
                  {"driver 'push' (joint 'rail')", "neither a smaller step nor another integrator"},
                  {"raise solver.max_steps", "hht carries"}});
}

TEST(NumericalFaults, GasVolumeDrivenToZeroIsTheGasVolumeNotTheStep) {
  // V0 + A s = 2 - 0.5 (4 t) is gone at t = 1 s; a step of 1 ms is stable for the gas
  // spring, so the element's own diagnosis stands, with the driver in its remedy.
  for (const std::string method : {"rk4", "ida", "hht"})
    expect_fault({"tests/cases/fault_gas_volume_driven.yaml", "--set solver.integrator=" + method, 0.99, 1.01,
                  {"accumulator"},
                  {"the gas volume is gone", "driver"},
                  {"stability limit", "solver.step <="}});
}

TEST(NumericalFaults, ExpressionWithoutRealValueIsBadInputBeforeAnyIntegratorRuns) {
  // sqrt(0.5 - t) has no real value after t = 0.5 s. An expression of t alone is checked
  // over the run before it starts (issue #13 class 6), so it is bad input at its key
  // under every integrator, never a numerical failure at some step.
  for (const std::string method : {"rk4", "dopri5", "ida", "hht"}) {
    const testing::CommandResult result = testing::run_command_line(
        testing::heavesim_binary() + " check " + testing::source_path("tests/cases/fault_expression_nan.yaml") +
        " --set solver.integrator=" + method);
    EXPECT_EQ(result.exit_code, 2) << method << ": " << result.output;
    EXPECT_NE(result.output.find("fault_expression_nan.yaml:11:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(": forces[0].torque: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("is not finite at t = 0.501 s"), std::string::npos) << result.output;
  }
}

}  // namespace
}  // namespace heavesim
