#include "validation/checks/n_four_bar_run.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "validation/checks/validation_suite.hpp"
#include "kernel/elements/body_point.hpp"
#include "validation/oracles/four_bar_parallelogram.hpp"

namespace heavesim::validation {

NFourBarErrors run_n_four_bar(const std::string& case_path, int windows) {
  std::vector<double> times;
  std::vector<Vector3> tip_positions;
  double branch_error = 0.0;
  const RunOutcome outcome = run_case_to_failure(case_path, {}, [&](double t, const MultibodySystem& system) {
      const Model& model = system.model();
      times.push_back(t);
      // coupler0's frame sits on crank0's tip, B0.
      tip_positions.push_back(BodyPoint::on_body(model, "coupler0", Vector3::Zero()).position_world(system.data()));
      const VectorX& q = system.configuration();
      const double q0 = q[model.joints[model.joint_index("pivot0")].q_index];
      for (int crank = 1; crank <= windows; ++crank)
        branch_error = std::max(
            branch_error, std::abs(q[model.joints[model.joint_index(fmt::format("pivot{}", crank))].q_index] - q0));
      for (int coupler = 0; coupler < windows; ++coupler) {
        const double crank = q[model.joints[model.joint_index(fmt::format("pivot{}", coupler))].q_index];
        const double tip = q[model.joints[model.joint_index(fmt::format("tip{}", coupler))].q_index];
        branch_error = std::max(branch_error, std::abs(crank + tip));  // coupler angle in the world
      }
    });
  NFourBarErrors errors;  // a run that stops is reported as an infinite error
  errors.completed = outcome.completed;
  errors.time_reached = outcome.time_reached;
  errors.tip_error = outcome.completed ? 0.0 : std::numeric_limits<double>::infinity();
  errors.branch_error = branch_error;
  if (outcome.completed) {
    std::vector<double> later(times.begin() + 1, times.end());
    const std::vector<double> angles = oracle::four_bar_crank_angles(windows, g, later, 1e-13);
    for (std::size_t k = 0; k < later.size(); ++k) {
      const Vector3 exact(-std::sin(angles[k]), std::cos(angles[k]), 0.0);
      errors.tip_error = std::max(errors.tip_error, (tip_positions[k + 1] - exact).norm());
    }
  } else {
    errors.branch_error = std::numeric_limits<double>::infinity();
  }
  return errors;
}

}  // namespace heavesim::validation
