// L5: an over-constrained planar parallelogram (cases/validation/overconstrained_four_bar.yaml):
// three parallel cranks and one 2 m coupler, closed by two 3-D revolute loop joints.
// 10 constraint rows of which 7 repeat others (3 out-of-plane rows per loop, and the
// third crank's in-plane row), mobility 1. References: the exact rank count at assembly,
// and the exact one-coordinate parallelogram motion (oracles/four_bar_parallelogram,
// parallelogram_crank_angles): crank0's tip against (sin q, -cos q), all cranks at q, the
// coupler level. The cranks swing to ~53 degrees, far from the flat singular position.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/elements/body_point.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/four_bar_parallelogram.hpp"

namespace heavesim::validation {

namespace {
constexpr const char* four_bar_case = "cases/validation/overconstrained_four_bar.yaml";
}

std::vector<ValidationRow> check_l5_overconstrained_four_bar() {
  std::vector<ValidationRow> rows =
      assembly_structure_rows("L5", "L5 parallelogram + 3rd crank", four_bar_case, 7, 1);

  // Three uniform 1 m, 1 kg cranks (centre 0.5 m, 1/3 kg m^2 about the pivot) and a
  // translating 2 kg coupler hung at the tips (1 m from the pivots).
  const double first_moment = 3 * 0.5 + 2.0 * 1.0;           // kg m
  const double second_moment = 3 * (1.0 / 3.0) + 2.0 * 1.0;  // kg m^2
  for (const auto& [label, overrides] :
       {std::pair<std::string, std::vector<std::string>>{"HHT index-3, h = 0.1 ms", {"solver.step=1e-4"}},
        {"Dormand-Prince + projection, rtol = atol = 1e-10", {"solver.integrator=dopri5"}}}) {
    std::vector<double> times;
    std::vector<Vector3> tips;
    double branch_error = 0.0;
    const RunOutcome outcome =
        run_case_to_failure(four_bar_case, overrides, [&](double t, const MultibodySystem& system) {
        const Model& model = system.model();
        const VectorX& q = system.configuration();
        times.push_back(t);
        // The coupler's frame sits on crank0's tip.
        tips.push_back(BodyPoint::on_body(model, "coupler", Vector3::Zero()).position_world(system.data()));
        const double q0 = q[model.joints[model.joint_index("pivot0")].q_index];
        for (const char* crank : {"pivot1", "pivot2"})
          branch_error = std::max(branch_error, std::abs(q[model.joints[model.joint_index(crank)].q_index] - q0));
        branch_error = std::max(branch_error, std::abs(q0 + q[model.joints[model.joint_index("tip0")].q_index]));
      });
    double tip_error = std::numeric_limits<double>::infinity();
    if (outcome.completed) {
      const std::vector<double> later(times.begin() + 1, times.end());
      const std::vector<double> angles =
          oracle::parallelogram_crank_angles(first_moment, second_moment, g, 0.0, 3.0, later, 1e-13);
      tip_error = 0.0;
      for (std::size_t k = 0; k < later.size(); ++k)
        tip_error = std::max(tip_error, (tips[k + 1] - Vector3(std::sin(angles[k]), -std::cos(angles[k]), 0.0)).norm());
    } else {
      branch_error = std::numeric_limits<double>::infinity();
    }
    const std::string subject = outcome.completed
                                    ? fmt::format("L5 over-constrained parallelogram 10 s, {}", label)
                                    : fmt::format("L5 10 s, {}: stopped at t = {:.3f} s", label, outcome.time_reached);
    rows.push_back({"L5", subject, "crank0 tip vs exact parallelogram motion [m]", tip_error, 1e-6});
    rows.push_back({"L5", subject, "on branch: cranks equal, coupler level [rad]", branch_error, 1e-6});
  }
  return rows;
}

}  // namespace heavesim::validation
