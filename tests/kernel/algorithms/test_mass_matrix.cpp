// The composite-rigid-body mass matrix against the double pendulum's closed form and,
// on random trees of every joint type, against inverse dynamics: column j of M is
// RNEA(q, v, e_j) - RNEA(q, v, 0) (the bias cancels, RNEA being affine in qdd).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "samples/planar_chains.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(MassMatrix, DoublePendulumMatchesTheClosedForm) {
  // Relative angles: with l1 the upper length, a_i the CoM distances, I_i about the CoMs,
  //   M11 = I1 + m1 a1^2 + I2 + m2 (l1^2 + a2^2 + 2 l1 a2 cos q2),
  //   M12 = I2 + m2 (a2^2 + l1 a2 cos q2),  M22 = I2 + m2 a2^2.
  const double l1 = 1.2, m1 = 2.0, a1 = 0.5, I1 = 0.3, m2 = 1.5, a2 = 0.4, I2 = 0.1;
  const Model model = samples::planar_chain({{l1, m1, a1, I1}, {0.8, m2, a2, I2}});
  Data data(model);
  for (const double q2 : {0.0, 0.9, -2.4}) {
    VectorX q(2);
    q << 0.3, q2;
    const MatrixX M = crba(model, data, q);
    Eigen::Matrix2d expected;
    expected(0, 0) = I1 + m1 * a1 * a1 + I2 + m2 * (l1 * l1 + a2 * a2 + 2 * l1 * a2 * std::cos(q2));
    expected(0, 1) = expected(1, 0) = I2 + m2 * (a2 * a2 + l1 * a2 * std::cos(q2));
    expected(1, 1) = I2 + m2 * a2 * a2;
    // Entries of order 5 kg m^2: bound 1e-14 relative to the largest.
    EXPECT_LT((M - expected).norm(), 1e-14 * expected.norm()) << "q2 = " << q2;
  }
}

TEST(MassMatrix, ColumnsAreInverseDynamicsOfUnitAccelerations) {
  std::mt19937_64 random(31);
  for (int trial = 0; trial < 5; ++trial) {
    const samples::RandomTreeAndState drawn = samples::random_tree_and_state(random, 14, trial % 2 == 0);
    const Model& model = drawn.model;
    const samples::RandomState& state = drawn.state;
    Data data(model);
    const MatrixX M = crba(model, data, state.q);
    const VectorX bias = rnea(model, data, state.q, state.v, VectorX::Zero(model.nv));
    for (int j = 0; j < model.nv; ++j) {
      const VectorX column = rnea(model, data, state.q, state.v, VectorX::Unit(model.nv, j)) - bias;
      // The difference cancels the bias (gravity, velocity products, of order |bias|):
      // round-off ~ depth x eps x |bias|, bounded by 1e-12 (1 + |bias|).
      EXPECT_LT((M.col(j) - column).norm(), 1e-12 * (1.0 + bias.norm())) << "trial " << trial << " column " << j;
    }
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  }
}

}  // namespace
}  // namespace heavesim
