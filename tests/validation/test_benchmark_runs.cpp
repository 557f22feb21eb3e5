// IFToMM A02 at N = 10 (20 s) on its own: the A02 validation check also runs N = 40
// (~30 s), which CTest leaves to `heavesim validate` (docs/validation.md, Benchmark
// results). Release only: 100 000 HHT steps on 21 bodies. And Bricard's mechanism with
// the explicit methods.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "validation/checks/n_four_bar_run.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {
namespace {

TEST(BenchmarkRuns, NFourBarWithTenWindowsStaysOnTheExactMotionFor20Seconds) {
  const NFourBarErrors errors = run_n_four_bar("cases/validation/iftomm_a02_n10.yaml", 10);
  EXPECT_TRUE(errors.completed);
  EXPECT_LE(errors.tip_error, 1e-6);     // m, B0 vs the exact parallelogram motion
  EXPECT_LE(errors.branch_error, 1e-6);  // rad, cranks equal and couplers level
}


// Bricard's mechanism (IFToMM A04: Grubler counts 0 degrees of freedom, it has 1, so
// one loop row is redundant) with the explicit methods at every tolerance they accept:
// each used to stop after 0.3-3.4 s with a false "singular configuration" (the KKT
// solve at stage values off the manifold, where the redundant row regains rank). No
// force does work but gravity, so kinetic + gravitational energy must stay constant to
// about the tolerance (measured drift: 1e-9..1e-5 of 5 m g L).
TEST(BenchmarkRuns, BricardRunsWithEveryExplicitMethodAtEveryToleranceConservingEnergy) {
  for (const std::string integrator : {"dopri5", "verner6", "fehlberg8"}) {
    for (double tolerance : {1e-6, 1e-8, 1e-10, 1e-12}) {
      double first = std::numeric_limits<double>::quiet_NaN(), drift = 0.0;
      const RunOutcome outcome = run_case(
          "cases/validation/iftomm_a04_bricard.yaml",
          {"solver.integrator=" + integrator, fmt::format("solver.rtol={:g}", tolerance),
           fmt::format("solver.atol={:g}", tolerance)},
          [&](double, const MultibodySystem& system) {
            const double energy = mechanical_energy(system);
            if (std::isnan(first)) first = energy;
            drift = std::max(drift, std::abs(energy - first));
          });
      const std::string label = fmt::format("{} at {:g}", integrator, tolerance);
      EXPECT_TRUE(outcome.completed) << label;
      // 5 rods of 1 kg, 1 m: m g L = 9.81 J per rod.
      EXPECT_LE(drift / (5 * 9.81), std::max(1e3 * tolerance, 1e-9)) << label;
    }
  }
}

}  // namespace
}  // namespace heavesim::validation
