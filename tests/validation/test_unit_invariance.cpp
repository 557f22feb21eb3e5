// Unit invariance: the same mechanism written in SI and in millimetres and grams (every
// length and mass times 1000) must run with the same success and the same accuracy at
// every tolerance, with every integrator. Angles and time do not change with those
// units, so nothing in the integrators may carry an absolute floor in metres, newtons
// or kilograms: a floor makes the result depend on how the user wrote the case (issue:
// IDA's multipliers had a 1e-5 floor in Newton's test, and Andrews' mechanism failed at
// t = 0 in SI but ran in mm-g-s; then, with that floor gone, the GGL equations' rows
// in N m against rad/s left IDA 20 times less accurate in SI than in mm-g-s at 1e-10).
// The one setting in length units, the constraint tolerance, is scaled with the case as a user would. A loop mechanism (Andrews', 7
// angles, 6 loop equations in metres) and a tree (a 3-rod chain with a spring) are run;
// both runs must succeed and reach the same accuracy against the true motion (Andrews:
// the test set's reference; the chain: an SI run of Fehlberg 8(7) at 1e-13) within a
// factor 5. Not identical digits: the two runs differ by round-off, and an adaptive
// method's accept/reject (and BDF's order) decisions turn a round-off difference into
// a different step sequence, whose results differ by about the tolerance: IDA on
// Andrews at rtol = atol = 1e-10 has error 1.3e-9, at 1.0000001e-10 1.9e-8, at
// 0.9999999e-10 6.8e-9; and a lucky cancellation can put one run an order below its
// tolerance (DOPRI5 at 1e-8 on Andrews once gave 5.1e-10 in SI, 4.6e-9 in mm-g-s, after
// a change of M's round-off). So an adaptive method's accuracy at a tolerance is taken
// as the geometric mean of its errors at tol / 1.1, tol and 1.1 tol: three step
// sequences that differ in more than round-off (with factors 1 -+ 1e-6 the three runs
// often shared one sequence and the mean smoothed nothing).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/andrews_reference.hpp"

namespace heavesim::validation {
namespace {

struct Method {
  std::string integrator;
  bool fixed_step;
};

const std::vector<Method> methods = {{"ida", false},    {"dopri5", false}, {"verner6", false},
                                     {"fehlberg8", false}, {"rk4", true},  {"hht", true}};

/// Final angles of the named joints, or an empty vector when the run fails.
std::vector<double> final_angles(const std::string& path, const std::vector<std::string>& overrides,
                                 const std::vector<std::string>& joints) {
  std::vector<double> angles(joints.size());
  const RunOutcome outcome = run_case_to_failure(path, overrides, [&](double, const MultibodySystem& system) {
    const Model& model = system.model();
    for (std::size_t i = 0; i < joints.size(); ++i)
      angles[i] = system.configuration()[model.joints[model.joint_index(joints[i])].q_index];
  });
  if (!outcome.completed) return {};
  return angles;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

/// Settings of one run: the method, its tolerance (or step), the constraint tolerance
/// in the case's length unit.
std::vector<std::string> settings(const Method& method, double tolerance, double step, double constraint_tolerance) {
  std::vector<std::string> out = {"solver.integrator=" + method.integrator,
                                  fmt::format("solver.constraint_tolerance={:g}", constraint_tolerance)};
  if (method.fixed_step) {
    out.push_back(fmt::format("solver.step={:g}", step));
    out.push_back("solver.rtol=1e-10");
    out.push_back("solver.atol=1e-10");
  } else {
    out.push_back(fmt::format("solver.rtol={:g}", tolerance));
    out.push_back(fmt::format("solver.atol={:g}", tolerance));
  }
  return out;
}

/// The accuracy of `method` at `tolerance` (or its fixed step) on `path` with
/// `overrides`: the largest angle error against `truth`, the geometric mean over three
/// tolerances 10 % apart for an adaptive method (errors below 1e-11 rad, the
/// round-off of a run and the reference's own digits, count as 1e-11); infinite when a
/// run fails.
double accuracy(const std::string& path, const Method& method, double tolerance, double step,
                double constraint_tolerance, const std::vector<std::string>& overrides,
                const std::vector<std::string>& joints, const std::vector<double>& truth) {
  const std::vector<double> factors = method.fixed_step ? std::vector<double>{1.0} : std::vector<double>{1 / 1.1, 1.0, 1.1};
  double log_sum = 0.0;
  for (double factor : factors) {
    std::vector<std::string> run_settings = settings(method, tolerance * factor, step, constraint_tolerance);
    run_settings.insert(run_settings.end(), overrides.begin(), overrides.end());
    const std::vector<double> angles = final_angles(path, run_settings, joints);
    if (angles.empty()) return std::numeric_limits<double>::infinity();
    log_sum += std::log(std::max(largest_difference(angles, truth), 1e-11));
  }
  return std::exp(log_sum / static_cast<double>(factors.size()));
}

void expect_same_accuracy(const std::string& label, double error_si, double error_mm) {
  std::printf("%-16s error SI %.2e, mm-g-s %.2e\n", label.c_str(), error_si, error_mm);
  ASSERT_TRUE(std::isfinite(error_si)) << label << ": the SI run failed";
  ASSERT_TRUE(std::isfinite(error_mm)) << label << ": the mm-g-s run failed";
  EXPECT_LE(std::max(error_si, error_mm), 5.0 * std::min(error_si, error_mm)) << label;
}

TEST(UnitInvariance, AndrewsMechanismRunsAlikeInSiAndInMillimetresAndGrams) {
  const std::vector<std::string> joints(oracle::andrews_joint_names.begin(), oracle::andrews_joint_names.end());
  std::vector<double> reference(oracle::andrews_reference_positions.begin(), oracle::andrews_reference_positions.end());
  for (const Method& method : methods) {
    // Tolerances 1e-4 .. 1e-10 (steps 1e-5 .. 1e-6 s for the fixed-step methods).
    for (int level = 0; level < 4; ++level) {
      const double tolerance = std::pow(10.0, -4 - 2 * level), step = level < 2 ? 1e-5 : 2e-6;
      if (method.fixed_step && level % 2 == 1) continue;
      const std::string label = fmt::format("{} {:g}", method.integrator, method.fixed_step ? step : tolerance);
      expect_same_accuracy(
          label,
          accuracy("cases/validation/iftomm_a03_andrews.yaml", method, tolerance, step, 1e-10, {}, joints, reference),
          accuracy("cases/validation/iftomm_a03_andrews_mm_g.yaml", method, tolerance, step, 1e-7, {}, joints, reference));
    }
  }
}

TEST(UnitInvariance, PendulumChainRunsAlikeInSiAndInMillimetresAndGrams) {
  const std::vector<std::string> joints = {"pin1", "pin2", "pin3"};
  const std::string path = "tests/cases/units_pendulum_chain.yaml";
  const std::vector<std::string> millimetres = {"parameters.length_unit=1000", "parameters.mass_unit=1000"};
  const auto truth = final_angles(path, {"solver.integrator=fehlberg8", "solver.rtol=1e-13", "solver.atol=1e-13"}, joints);
  ASSERT_FALSE(truth.empty());
  for (const Method& method : methods) {
    for (int level = 0; level < 4; ++level) {
      const double tolerance = std::pow(10.0, -4 - 2 * level), step = level < 2 ? 1e-3 : 1e-4;
      if (method.fixed_step && level % 2 == 1) continue;
      const std::string label = fmt::format("{} {:g}", method.integrator, method.fixed_step ? step : tolerance);
      expect_same_accuracy(label, accuracy(path, method, tolerance, step, 1e-10, {}, joints, truth),
                           accuracy(path, method, tolerance, step, 1e-7, millimetres, joints, truth));
    }
  }
}

}  // namespace
}  // namespace heavesim::validation
