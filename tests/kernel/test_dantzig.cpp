// Dantzig's principal pivoting for boxed MLCPs (kernel/complementarity/dantzig.hpp):
// random SPD problems with chosen answers, boxed problems cross-checked with Lemke's box
// expansion and projected Gauss-Seidel, the friction box scaled by the normal impulse
// against the closed form of a particle hitting a plane, and its failure statuses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "kernel/complementarity/dantzig.hpp"
#include "kernel/complementarity/lemke.hpp"
#include "kernel/complementarity/projected_gauss_seidel.hpp"
#include "samples/complementarity_problems.hpp"

namespace heavesim {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

TEST(Dantzig, SolvesRandomSpdProblemsToTheirChosenAnswers) {
  for (const int n : {10, 50, 200}) {
    const samples::LcpSample sample = samples::random_spd_lcp(n, 300 + n);
    DantzigWorkspace workspace(n);
    VectorX z(n);
    const ComplementarityResult result = dantzig({sample.M, sample.q}, workspace, z);
    ASSERT_TRUE(result.solved()) << "n = " << n << ": " << result.message;
    EXPECT_LE(result.residual, 1e-10);
    EXPECT_LE((z - sample.z).lpNorm<Eigen::Infinity>(), 1e-9) << "n = " << n;
  }
}

// Box conditions checked directly: lo <= z <= hi; w >= 0 where z = lo < hi, w <= 0
// where z = hi > lo, w = 0 strictly inside.
void expect_box_solution(const MatrixX& M, const VectorX& q, const VectorX& lo, const VectorX& hi,
                         const VectorX& z, double tolerance) {
  const VectorX w = M * z + q;
  for (int i = 0; i < z.size(); ++i) {
    EXPECT_GE(z[i], lo[i] - tolerance);
    EXPECT_LE(z[i], hi[i] + tolerance);
    if (z[i] <= lo[i] + tolerance) EXPECT_GE(w[i], -tolerance) << "row " << i;
    else if (z[i] >= hi[i] - tolerance) EXPECT_LE(w[i], tolerance) << "row " << i;
    else EXPECT_NEAR(w[i], 0.0, tolerance) << "row " << i;
  }
}

// On a symmetric positive definite M the boxed MLCP has one answer (it is the minimum of
// the strictly convex 1/2 z^T M z + q^T z over the box), so three different algorithms
// must agree to their round-off: Dantzig directly, Lemke on the 2n expansion, PGS.
TEST(Dantzig, AgreesWithLemkeAndProjectedGaussSeidelOnBoxedProblems) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int n : {5, 20, 60}) {
    const samples::LcpSample sample = samples::random_spd_lcp(n, 400 + n, 0.5);
    VectorX q(n), lo(n), hi(n);
    for (int i = 0; i < n; ++i) {
      q[i] = 4.0 * unit(random) - 2.0;
      lo[i] = i % 4 == 0 ? 0.0 : -unit(random);
      hi[i] = i % 5 == 0 ? infinity : unit(random);
    }
    const ComplementarityProblem problem{sample.M, q, lo, hi};
    DantzigWorkspace dantzig_workspace(n);
    LemkeWorkspace lemke_workspace(n);
    ProjectedGaussSeidelWorkspace pgs_workspace(n);
    VectorX z_dantzig(n), z_lemke(n), z_pgs(n);
    const ComplementarityResult by_dantzig = dantzig(problem, dantzig_workspace, z_dantzig);
    const ComplementarityResult by_lemke = lemke(problem, lemke_workspace, z_lemke);
    ProjectedGaussSeidelOptions pgs_options;
    pgs_options.max_iterations = 20000;
    pgs_options.tolerance = 1e-13;
    const ComplementarityResult by_pgs = projected_gauss_seidel(problem, pgs_workspace, z_pgs, pgs_options);
    ASSERT_TRUE(by_dantzig.solved()) << by_dantzig.message;
    ASSERT_TRUE(by_lemke.solved()) << by_lemke.message;
    ASSERT_TRUE(by_pgs.solved()) << by_pgs.message;
    expect_box_solution(sample.M, q, lo, hi, z_dantzig, 1e-12);
    // cond(M) <= ~10 for delta = 0.5: residuals of 1e-13 put the answers within ~1e-12.
    EXPECT_LE((z_dantzig - z_lemke).lpNorm<Eigen::Infinity>(), 1e-11) << "n = " << n;
    EXPECT_LE((z_dantzig - z_pgs).lpNorm<Eigen::Infinity>(), 1e-11) << "n = " << n;
  }
}

// A particle of mass m hits a frictional plane with velocity (v_n < 0, v_t1, v_t2); one
// impulse step with the friction pyramid: w = M z + q with M = I / m, q = v, z = (p_n, p_t1,
// p_t2), |p_ti| <= mu p_n. Closed form: p_n = -m v_n (the normal velocity vanishes); per
// tangent axis the particle sticks (p_ti = -m v_ti) if |v_ti| <= mu |v_n|, else slides
// with p_ti = -mu p_n sign(v_ti). Friction rows sit before the normal row on purpose.
TEST(Dantzig, ScalesTheFrictionBoxByTheNormalImpulse) {
  const double m = 2.0, mu = 0.4, v_n = -3.0;
  const MatrixX M = MatrixX::Identity(3, 3) / m;
  Eigen::VectorXi normal(3);
  normal << 2, 2, -1;
  const VectorX coefficient = VectorX::Constant(3, mu);
  for (const Eigen::Vector2d& tangential : {Eigen::Vector2d(0.5, -1.0), Eigen::Vector2d(2.0, -0.3)}) {
    VectorX q(3);
    q << tangential, v_n;
    const ComplementarityProblem problem{M, q, std::nullopt, std::nullopt, normal, coefficient};
    const double p_n = -m * v_n;
    VectorX expected(3);
    for (int k = 0; k < 2; ++k)
      expected[k] = std::abs(tangential[k]) <= mu * std::abs(v_n) ? -m * tangential[k]
                                                                 : -mu * p_n * std::copysign(1.0, tangential[k]);
    expected[2] = p_n;
    DantzigWorkspace workspace(3);
    VectorX z(3);
    const ComplementarityResult by_dantzig = dantzig(problem, workspace, z);
    ASSERT_TRUE(by_dantzig.solved()) << by_dantzig.message;
    EXPECT_LE((z - expected).lpNorm<Eigen::Infinity>(), 1e-14) << z.transpose();
    ProjectedGaussSeidelWorkspace pgs_workspace(3);
    VectorX z_pgs(3);
    const ComplementarityResult by_pgs = projected_gauss_seidel(problem, pgs_workspace, z_pgs);
    ASSERT_TRUE(by_pgs.solved()) << by_pgs.message;
    EXPECT_LE((z_pgs - expected).lpNorm<Eigen::Infinity>(), 1e-12) << z_pgs.transpose();
  }
}

// Two contact rows along the same direction (a duplicated contact point with another
// gap): M = [1 1; 1 1] is singular. Row 0 clamps at z = (1, 0), leaving w_1 = -1; driving
// row 1 with row 0 clamped changes w_1 at the rate of the Schur complement 1 - 1 = 0:
// the "s <= 0" of ODE and Bullet, here a status. (With equal gaps, q = (-1, -1), row 1
// is already complementary at z_1 = 0 and the solve succeeds.)
// Two contact rows along one direction with different gaps: M = [1 1; 1 1] is singular.
// Once row 1 is clamped, row 2's w no longer moves with z_2: z_2 grows while z_1 gives
// way, until row 1 leaves at 0; then z_2 alone closes its w. The answer is unique:
// w_2 = z_1 + z_2 - 2 >= 0 forces w_1 = w_2 + 1 > 0, so z_1 = 0 and z_2 = 2 (what Lemke
// finds on the same problem).
TEST(Dantzig, LetsADependentRowTakeOverFromTheClampedOne) {
  MatrixX M(2, 2);
  M << 1, 1, 1, 1;
  const VectorX q = Eigen::Vector2d(-1, -2);
  DantzigWorkspace workspace(2);
  VectorX z(2);
  const ComplementarityResult result = dantzig({M, q}, workspace, z);
  ASSERT_TRUE(result.solved()) << result.message;
  EXPECT_LE((z - Eigen::Vector2d(0, 2)).lpNorm<Eigen::Infinity>(), 1e-15);
  EXPECT_EQ(result.pivots, 3);
}

// A row whose w cannot move and whose box is open in the direction it must go: no step
// ends. M = [0 1; 1 0] has no solution Dantzig's pivots reach (nor Lemke's: it is not
// copositive-plus); the failure names the row.
TEST(Dantzig, ReportsASingularPivotWhereNoStepEnds) {
  MatrixX M(2, 2);
  M << 0, 1, 1, 0;
  const VectorX q = Eigen::Vector2d(-1, -1);
  DantzigWorkspace workspace(2);
  VectorX z(2);
  const ComplementarityResult result = dantzig({M, q}, workspace, z);
  EXPECT_EQ(result.status, ComplementarityStatus::singular_pivot);
  EXPECT_NE(result.message.find("pivot of row 0"), std::string::npos) << result.message;
}

// A friction row along a coordinate that a free row (a driver) holds: its w is the
// driven speed whatever its impulse, so it goes to its bound, and the free row takes the
// rest (a bit on the formation turned by the top drive: the drive supplies mu_t z_n).
TEST(Dantzig, SendsAFrictionRowThatTheDriverHoldsToItsBound) {
  // Rows: 0 the driver (free), 1 the normal, 2 the torsional friction of row 1 (mu 0.5).
  MatrixX M(3, 3);
  M << 2, 0, 2, 0, 1, 0, 2, 0, 2;
  const VectorX q = Eigen::Vector3d(-4, -3, 1);  // the normal needs 3; the spin is 1 without impulses
  const Eigen::Vector3d lower(-std::numeric_limits<double>::infinity(), 0, 0);
  const Eigen::Vector3d upper = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::VectorXi normal(3);
  normal << -1, -1, 1;
  const Eigen::Vector3d mu(0, 0, 0.5);
  DantzigWorkspace workspace(3);
  VectorX z(3);
  const ComplementarityResult result = dantzig({M, q, lower, upper, normal, mu}, workspace, z);
  ASSERT_TRUE(result.solved()) << result.message;
  // z_n = 3; the friction at -mu z_n = -1.5; the driver: w_0 = 2 z_0 + 2 z_2 - 4 = 0.
  EXPECT_LE((z - Eigen::Vector3d(3.5, 3, -1.5)).lpNorm<Eigen::Infinity>(), 1e-14);
}

TEST(Dantzig, RefusesANonSymmetricMatrix) {
  const samples::LcpSample sample = samples::random_p_matrix_lcp(4, 1);
  DantzigWorkspace workspace(4);
  VectorX z(4);
  const ComplementarityResult result = dantzig({sample.M, sample.q}, workspace, z);
  EXPECT_EQ(result.status, ComplementarityStatus::unsupported);
  EXPECT_NE(result.message.find("symmetric"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace heavesim
