// The tree-sparse L^T L factorization (kernel/algorithms/tree_factorization.hpp) against
// the dense Cholesky on random trees of every joint type: the factor reproduces M from the
// ancestor entries alone (no fill-in), and its solve agrees with the LLT solve.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/tree_factorization.hpp"
#include "samples/contact_scenes.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

void expect_factor_and_solve(const Model& model, const VectorX& q, std::mt19937_64& random) {
  Data data(model);
  const MatrixX M = crba(model, data, q);
  const std::vector<int>& parent = model.velocity_coordinate_parent;
  for (int c = 0; c < model.nv; ++c) ASSERT_LT(parent[c], c);
  // Entries that are not (descendant, ancestor) pairs must be unused: fill them with NaN.
  MatrixX factor = MatrixX::Constant(model.nv, model.nv, std::nan(""));
  for (int i = 0; i < model.nv; ++i)
    for (int j = i; j >= 0; j = parent[j]) factor(i, j) = M(i, j);
  ASSERT_TRUE(factorize_tree(parent, factor));
  MatrixX L = MatrixX::Zero(model.nv, model.nv);
  for (int i = 0; i < model.nv; ++i)
    for (int j = i; j >= 0; j = parent[j]) L(i, j) = factor(i, j);
  EXPECT_LE((L.transpose() * L - M).norm(), 1e-12 * M.norm());
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX x(model.nv);
  for (double& entry : x) entry = uniform(random);
  const VectorX expected = M.llt().solve(x);
  solve_tree(parent, factor, x);
  EXPECT_LE((x - expected).norm(), 1e-10 * expected.norm());
}

TEST(TreeFactorization, MatchesTheDenseCholeskyOnRandomTrees) {
  std::mt19937_64 random(77);
  for (int trial = 0; trial < 6; ++trial) {
    samples::RandomTreeOptions options;
    options.bodies = 14;
    options.chain = trial % 3 == 2;
    options.added_inertia = trial % 2 == 1;
    const Model model = samples::random_tree(random, options);
    expect_factor_and_solve(model, samples::random_state(model, random).q, random);
  }
}

TEST(TreeFactorization, FreeBodiesFactorBlockByBlock) {
  // Five free cubes: M is block diagonal, each coordinate's parents stay in its own body.
  const samples::ContactScene stack = samples::box_stack(5, 1.0, 2.0, 10.0, 0.0);
  const std::vector<int>& parent = stack.model->velocity_coordinate_parent;
  for (int c = 0; c < stack.model->nv; ++c) EXPECT_EQ(parent[c], c % 6 == 0 ? -1 : c - 1);
  std::mt19937_64 random(5);
  expect_factor_and_solve(*stack.model, stack.q, random);
}

}  // namespace
}  // namespace heavesim
