// A02: IFToMM benchmark A02 at the benchmark's size: the N-four-bar with N = 10 and the
// specified N = 40 (81 bars, 40 loops) over 20 s (cases/validation/iftomm_a02_n10.yaml,
// n40.yaml, written by scripts/make_iftomm_a02.py), against the exact parallelogram
// motion (oracles/four_bar_parallelogram). Every crank lies flat at q = pi/2 + k pi,
// where the loop Jacobian loses N rows. B0 at every 0.01 s sample (the benchmark
// compares B0's x and y, at 1e-3 for "high precision"); a run that stops is an
// infinite error (docs/validation.md, A02).
#include <fmt/format.h>

#include "validation/checks/n_four_bar_run.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_a02_n_four_bar() {
  std::vector<ValidationRow> rows;
  for (int windows : {10, 40}) {
    const NFourBarErrors errors = run_n_four_bar(fmt::format("cases/validation/iftomm_a02_n{}.yaml", windows), windows);
    const std::string subject =
        errors.completed
            ? fmt::format("A02 N = {}, 20 s, HHT index-3, h = 0.2 ms", windows)
            : fmt::format("A02 N = {}, 20 s, HHT, h = 0.2 ms: stopped at t = {:.3f} s", windows, errors.time_reached);
    rows.push_back({"A02", subject, "B0 position vs the exact parallelogram motion [m]", errors.tip_error, 1e-6});
    rows.push_back({"A02", subject, "on branch: crank angles equal, couplers level [rad]", errors.branch_error, 1e-6});
  }
  return rows;
}

}  // namespace heavesim::validation
