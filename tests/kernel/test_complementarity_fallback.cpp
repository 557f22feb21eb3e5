// The fallback chain (kernel/complementarity/fallback_chain.hpp) and the input checks every
// solver shares (complementarity_problem.hpp: validate).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernel/complementarity/fallback_chain.hpp"
#include "samples/complementarity_problems.hpp"

namespace heavesim {
namespace {

// The 1:100 stack: projected Gauss-Seidel stalls within its 200 sweeps, Dantzig then
// solves it exactly; the result says so. Reference: the static impulses h g sum(m).
TEST(ComplementarityFallback, MovesOnFromAStalledGaussSeidelAndSaysWhichSolverAnswered) {
  const samples::LcpSample stack = samples::box_stack(10, 100.0);
  ComplementarityWorkspace workspace(10);
  VectorX z(10);
  FallbackChainOptions options;
  options.projected_gauss_seidel.max_iterations = 200;
  const ComplementarityResult result = solve_complementarity({stack.M, stack.q}, workspace, z, options);
  ASSERT_TRUE(result.solved()) << result.message;
  EXPECT_EQ(result.solver, ComplementaritySolver::dantzig);
  EXPECT_EQ(result.attempts, 2);
  EXPECT_NE(result.message.find("projected Gauss-Seidel: not converged"), std::string::npos) << result.message;
  // Tridiagonal with condition ~10^4: a relative 1e-12 after elimination.
  EXPECT_LE((z - stack.z).lpNorm<Eigen::Infinity>(), 1e-12 * stack.z[0]);
}

// A non-symmetric P-matrix (a frictional problem written as an LCP has one): Dantzig,
// which needs a symmetric M, refuses it and Lemke solves it; the result says so.
TEST(ComplementarityFallback, LemkeAnswersWhereDantzigRefusesANonSymmetricMatrix) {
  const samples::LcpSample sample = samples::random_p_matrix_lcp(6, 3);
  ComplementarityWorkspace workspace(6);
  VectorX z(6);
  FallbackChainOptions options;
  options.order = {ComplementaritySolver::dantzig, ComplementaritySolver::lemke, ComplementaritySolver::lemke};
  options.count = 2;
  const ComplementarityResult result = solve_complementarity({sample.M, sample.q}, workspace, z, options);
  ASSERT_TRUE(result.solved()) << result.message;
  EXPECT_EQ(result.solver, ComplementaritySolver::lemke);
  EXPECT_NE(result.message.find("Dantzig: unsupported"), std::string::npos) << result.message;
  EXPECT_LE((z - sample.z).lpNorm<Eigen::Infinity>(), 1e-12 * (1.0 + sample.z.lpNorm<Eigen::Infinity>()));
}

// No solution (infeasible): every solver fails and the chain lists them all.
TEST(ComplementarityFallback, ReportsEverySolversFailureWhenNoneSolves) {
  MatrixX M(2, 2);
  M << 1, 0, 0, -1;  // w2 = -z2 - 1 < 0 for every z2 >= 0: infeasible
  const VectorX q = Eigen::Vector2d(-1, -1);
  ComplementarityWorkspace workspace(2);
  VectorX z(2);
  const ComplementarityResult result = solve_complementarity({M, q}, workspace, z);
  EXPECT_FALSE(result.solved());
  EXPECT_EQ(result.attempts, 3);
  for (const char* part : {"projected Gauss-Seidel: singular pivot", "Dantzig: singular pivot", "Lemke: ray termination"})
    EXPECT_NE(result.message.find(part), std::string::npos) << part << " in " << result.message;
}

ComplementarityResult checked(const ComplementarityProblem& problem) {
  ComplementarityWorkspace workspace(4);
  VectorX z(problem.q.size());
  return solve_complementarity(problem, workspace, z);
}

void expect_invalid(const ComplementarityResult& result, const std::string& part) {
  EXPECT_EQ(result.status, ComplementarityStatus::invalid_input) << result.message;
  EXPECT_NE(result.message.find(part), std::string::npos) << "'" << part << "' in: " << result.message;
  EXPECT_EQ(result.attempts, 1);
}

TEST(ComplementarityFallback, RefusesInvalidInputNamingTheEntry) {
  const MatrixX square = MatrixX::Identity(3, 3);
  const VectorX q = -VectorX::Ones(3);
  expect_invalid(checked({MatrixX::Identity(3, 2), q}), "matrix M is 3 x 2, expected square");
  expect_invalid(checked({square, VectorX::Ones(2)}), "vector q has 2 entries, expected 3");
  MatrixX with_nan = square;
  with_nan(2, 1) = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(checked({with_nan, q}), "M(2, 1)");
  VectorX q_infinite = q;
  q_infinite[1] = std::numeric_limits<double>::infinity();
  expect_invalid(checked({square, q_infinite}), "q(1)");
  const VectorX lo = Eigen::Vector3d(0, 1, 0), hi = Eigen::Vector3d(1, 0.5, 1);
  expect_invalid(checked({square, q, lo, hi}), "row 1: bounds [1.000000, 0.500000]");
  const VectorX short_lo = VectorX::Zero(2);
  expect_invalid(checked({square, q, short_lo}), "lower bound lo has 2 entries, expected 3");
  Eigen::VectorXi normal(3);
  normal << -1, 0, 0;
  const VectorX negative_mu = Eigen::Vector3d(0, 0.3, -0.1);
  expect_invalid(checked({square, q, std::nullopt, std::nullopt, normal, negative_mu}),
                 "friction row 2: coefficient mu = -0.100000, expected finite and >= 0");
  Eigen::VectorXi out_of_range(3);
  out_of_range << -1, 7, 0;
  const VectorX mu = VectorX::Constant(3, 0.3);
  expect_invalid(checked({square, q, std::nullopt, std::nullopt, out_of_range, mu}), "friction row 1: normal index 7");
}

TEST(ComplementarityFallback, LemkeRefusesABadCoveringVector) {
  const MatrixX M = MatrixX::Identity(2, 2);
  const VectorX q = -VectorX::Ones(2);
  const VectorX d = Eigen::Vector2d(1, 0);
  LemkeWorkspace workspace(2);
  VectorX z(2);
  LemkeOptions options;
  options.covering_vector = &d;
  expect_invalid(lemke({M, q}, workspace, z, options), "covering vector d needs 2 finite entries > 0");
}

}  // namespace
}  // namespace heavesim
