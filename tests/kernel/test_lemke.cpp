// Lemke's method (kernel/complementarity/lemke.hpp) against the worked tableau example of
// the source document, Murty's exponential family, a degenerate problem on which the
// first-row tie rule cycles, and random SPD and P-matrix problems whose answer was chosen
// before q was formed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/complementarity/lemke.hpp"
#include "samples/complementarity_problems.hpp"

namespace heavesim {
namespace {

using Kind = LemkeVariable::Kind;

/// Checks z >= 0, w = M z + q >= 0 and z_i w_i = 0 directly, to `tolerance` times |q|_inf.
void expect_lcp_solution(const MatrixX& M, const VectorX& q, const VectorX& z, double tolerance) {
  const VectorX w = M * z + q;
  const double scale = q.lpNorm<Eigen::Infinity>();
  for (int i = 0; i < z.size(); ++i) {
    EXPECT_GE(z[i], -tolerance * scale) << "row " << i;
    EXPECT_GE(w[i], -tolerance * scale) << "row " << i;
    EXPECT_LE(std::abs(std::min(z[i], w[i])), tolerance * scale) << "row " << i;
  }
}

// The quadratic program of the source document (section 2.1.3, tables 3-2 to 3-5):
//   min f(x) = 1/2 (2 x1^2 - 2 x1 x2 + 10 x2^2) - x1 - 10 x2,  3 x1 + 2 x2 <= 6,  x >= 0.
// Its KKT conditions are the LCP with z = (x, u) (u the constraint's multiplier):
//   M = [H A^T; -A 0], q = [c; b]. The tables pivot (z0 in, w2 out), (z2 in, w1 out),
//   (z1 in, z0 out) and end at x = (20/19, 21/19), u = 0, slack w3 = 12/19.
TEST(Lemke, SolvesTheSourceDocumentsTableauExampleWithItsPivotSequence) {
  Eigen::Matrix2d H;
  H << 2, -1, -1, 10;
  const Eigen::Vector2d c(-1, -10);
  const Eigen::RowVector2d A(3, 2);
  const double b = 6;
  MatrixX M = MatrixX::Zero(3, 3);
  M.topLeftCorner(2, 2) = H;
  M.topRightCorner(2, 1) = A.transpose();
  M.bottomLeftCorner(1, 2) = -A;
  VectorX q(3);
  q << c, b;
  // The source's table 3-2 prints -M and q: rows (-2, 1, -3 | -1), (1, -10, -2 | -10), (3, 2, 0 | 6).
  MatrixX printed(3, 3);
  printed << -2, 1, -3, 1, -10, -2, 3, 2, 0;
  ASSERT_EQ(-M, printed);
  ASSERT_EQ(q, Eigen::Vector3d(-1, -10, 6));

  LemkeWorkspace workspace(3);
  std::vector<LemkePivot> pivots;
  pivots.reserve(8);
  LemkeOptions options;
  options.pivot_log = &pivots;
  VectorX z(3);
  const ComplementarityResult result = lemke({M, q}, workspace, z, options);
  ASSERT_TRUE(result.solved()) << result.message;
  // 0-based indices: the source's w2 is w(1).
  const std::vector<LemkePivot> source_sequence{{{Kind::covering, 0}, {Kind::w, 1}},
                                                {{Kind::z, 1}, {Kind::w, 0}},
                                                {{Kind::z, 0}, {Kind::covering, 0}}};
  EXPECT_EQ(pivots, source_sequence);
  EXPECT_EQ(result.pivots, 3);
  // Table 3-5: z1 = 20/19, z2 = 21/19, w3 = 12/19 (the fractions are exact in the
  // tableau; a few ulps of round-off in ours).
  EXPECT_NEAR(z[0], 20.0 / 19.0, 4e-16);
  EXPECT_NEAR(z[1], 21.0 / 19.0, 4e-16);
  EXPECT_EQ(z[2], 0.0);
  EXPECT_NEAR((M * z + q)[2], 12.0 / 19.0, 1e-15);
  // The QP's own optimality: H x + c = 0 at the interior optimum of the objective.
  EXPECT_LT((H * z.head(2) + c).norm(), 1e-14);
}

// Murty (1978; Linear Complementarity, 1988, ch. 6): on M lower triangular (1 on the
// diagonal, 2 below) with q_i = -(2^n + ... + 2^(n+1-i)), Lemke's method with d = 1 visits
// 2^n bases: exactly 2^n pivots, counting z0's entry and exit.
TEST(Lemke, NeedsTwoToTheNPivotsOnMurtysProblem) {
  for (int n = 2; n <= 8; ++n) {
    const samples::LcpSample murty = samples::murty_problem(n);
    LemkeWorkspace workspace(n);
    VectorX z(n);
    const ComplementarityResult result = lemke({murty.M, murty.q}, workspace, z);
    ASSERT_TRUE(result.solved()) << "n = " << n << ": " << result.message;
    EXPECT_EQ(result.pivots, 1 << n) << "n = " << n;
    EXPECT_EQ(z, murty.z) << "n = " << n;  // integers: exact
  }
}

// A degenerate problem (two rows tie at z0's entry, and the ratio tests tie again) found by
// a search over small integer matrices: with the first tied row leaving, the method runs
// round the four bases (z0 w1 w2 -> ...) forever; the lexicographic rule reaches the answer
// z = (0, 2, 0), w = (2, 0, 1) in two pivots.
TEST(Lemke, LexicographicRuleEndsADegenerateProblemThatCyclesOtherwise) {
  MatrixX M(3, 3);
  M << 0, 2, 0, 1, 1, -2, -2, 0, 2;
  const VectorX q = Eigen::Vector3d(-2, -2, 1);
  LemkeWorkspace workspace(3);
  VectorX z(3);
  std::vector<LemkePivot> pivots;
  pivots.reserve(64);
  LemkeOptions first_row;
  first_row.tie_break = LemkeTieBreak::first_row;
  first_row.max_pivots = 50;
  first_row.pivot_log = &pivots;
  const ComplementarityResult cycling = lemke({M, q}, workspace, z, first_row);
  EXPECT_EQ(cycling.status, ComplementarityStatus::iteration_limit);
  EXPECT_EQ(cycling.pivots, 50);
  ASSERT_EQ(pivots.size(), 50u);
  for (std::size_t k = 2; k + 4 < pivots.size(); ++k) EXPECT_EQ(pivots[k], pivots[k + 4]) << "pivot " << k;

  const ComplementarityResult result = lemke({M, q}, workspace, z);
  ASSERT_TRUE(result.solved()) << result.message;
  EXPECT_EQ(result.pivots, 2);
  EXPECT_EQ(z, Eigen::Vector3d(0, 2, 0));
  EXPECT_EQ(VectorX(M * z + q), Eigen::Vector3d(2, 0, 1));
}

// P2: the answer (z*, w*) is drawn first and q = w* - M z*; for a P-matrix it is the
// only one. Bar: relative natural-map residual <= 1e-10. Ours reaches a few 1e-15 after
// the refinement step; the distance to z* is bounded by cond(M) times that (cond <= ~10^3
// for delta = 0.1 at n = 500).
TEST(Lemke, SolvesRandomSpdAndPMatrixProblemsToTheirChosenAnswers) {
  for (const int n : {10, 50, 200, 500}) {
    for (const bool symmetric : {true, false}) {
      const samples::LcpSample sample =
          symmetric ? samples::random_spd_lcp(n, 100 + n) : samples::random_p_matrix_lcp(n, 200 + n);
      LemkeWorkspace workspace(n);
      VectorX z(n);
      const ComplementarityResult result = lemke({sample.M, sample.q}, workspace, z);
      ASSERT_TRUE(result.solved()) << "n = " << n << ": " << result.message;
      EXPECT_LE(result.residual, 1e-10) << "n = " << n;
      expect_lcp_solution(sample.M, sample.q, z, 1e-10);
      EXPECT_LE((z - sample.z).lpNorm<Eigen::Infinity>(), 1e-9) << "n = " << n << (symmetric ? " SPD" : " P");
    }
  }
}

TEST(Lemke, AnyPositiveCoveringVectorReachesTheSameUniqueAnswer) {
  const samples::LcpSample sample = samples::random_spd_lcp(30, 7);
  LemkeWorkspace workspace(30);
  VectorX z(30);
  const VectorX d = VectorX::LinSpaced(30, 1.0, 3.0);
  LemkeOptions options;
  options.covering_vector = &d;
  const ComplementarityResult result = lemke({sample.M, sample.q}, workspace, z, options);
  ASSERT_TRUE(result.solved()) << result.message;
  EXPECT_LE((z - sample.z).lpNorm<Eigen::Infinity>(), 1e-12);
}

// M skew-symmetric is positive semidefinite, hence copositive-plus; with q = (-1, -1) the
// LCP is infeasible (w2 = -z1 - 1 < 0 for every z1 >= 0), and Lemke's theorem says the
// method must end on a ray.
TEST(Lemke, EndsOnARayForAnInfeasibleCopositivePlusProblem) {
  MatrixX M(2, 2);
  M << 0, 1, -1, 0;
  const VectorX q = Eigen::Vector2d(-1, -1);
  LemkeWorkspace workspace(2);
  VectorX z(2);
  const ComplementarityResult result = lemke({M, q}, workspace, z);
  EXPECT_EQ(result.status, ComplementarityStatus::ray_termination);
  EXPECT_NE(result.message.find("ray termination"), std::string::npos) << result.message;
}

TEST(Lemke, ReachesTheTrivialAnswerWithoutPivotingWhenQIsNonnegative) {
  const MatrixX M = MatrixX::Identity(2, 2);
  const VectorX q = Eigen::Vector2d(1, 0);
  LemkeWorkspace workspace(2);
  VectorX z = VectorX::Constant(2, 5.0);
  const ComplementarityResult result = lemke({M, q}, workspace, z);
  ASSERT_TRUE(result.solved());
  EXPECT_EQ(result.pivots, 0);
  EXPECT_EQ(z, VectorX::Zero(2));
}

}  // namespace
}  // namespace heavesim
