// IFToMM A02 at N = 10 (20 s) on its own: the A02 validation check also runs N = 40,
// which stops today (docs/validation.md, Benchmark results), so the suite's
// EveryRowPassesItsBar cannot hold A02; this keeps the part that passes under test.
// Release only: 100 000 HHT steps on 21 bodies.
#include <gtest/gtest.h>

#include "validation/checks/n_four_bar_run.hpp"

namespace heavesim::validation {
namespace {

TEST(BenchmarkRuns, NFourBarWithTenWindowsStaysOnTheExactMotionFor20Seconds) {
  const NFourBarErrors errors = run_n_four_bar("cases/validation/iftomm_a02_n10.yaml", 10);
  EXPECT_TRUE(errors.completed);
  EXPECT_LE(errors.tip_error, 1e-6);     // m, B0 vs the exact parallelogram motion
  EXPECT_LE(errors.branch_error, 1e-6);  // rad, cranks equal and couplers level
}

}  // namespace
}  // namespace heavesim::validation
