// L2: IFToMM A02, the N-four-bar with N = 1 and 2 (cases/validation/iftomm_a02_n*.yaml)
// through the whole application, against the exact one-coordinate motion of the
// parallelogram branch. Every crank lies flat on the ground line at q = pi/2 + k pi:
// there the loop Jacobian loses N rows, the mechanism could leave the parallelogram
// branch, and tree-based peers do (docs/validation.md). Over 10 s the cranks pass
// about ten such configurations. Checked at every output sample (0.01 s): the first
// crank tip B0 against the exact (-sin q, cos q), and that the run stayed on the
// branch (all cranks at the same angle, the couplers level). The benchmark's own size
// (N = 10, 40 over 20 s) is check A02.
#include <fmt/format.h>

#include "validation/checks/n_four_bar_run.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_l2_four_bar() {
  std::vector<ValidationRow> rows;
  for (int windows : {1, 2}) {
    const NFourBarErrors errors =
        run_n_four_bar(fmt::format("cases/validation/iftomm_a02_n{}.yaml", windows), windows);
    const std::string subject = fmt::format("A02 N = {}, 10 s, HHT index-3, h = 0.2 ms", windows);
    rows.push_back({"L2", subject, "B0 position vs the exact parallelogram motion [m]", errors.tip_error, 1e-6});
    rows.push_back({"L2", subject, "on branch: crank angles equal, couplers level [rad]", errors.branch_error, 1e-6});
  }
  return rows;
}

}  // namespace heavesim::validation
