// The fixed-size Cholesky inverse against Eigen's LU with full pivoting (another
// factorization) and against the identity A A^{-1} = I, on random symmetric positive
// definite matrices of sizes 3 and 6 and condition numbers up to 1e8, and its NaN answer
// for a matrix that is not positive definite.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/LU>
#include <Eigen/QR>

#include "kernel/math/positive_definite_inverse.hpp"

namespace heavesim {
namespace {

template <int N>
void check_random_matrices(std::mt19937_64& random) {
  using Matrix = Eigen::Matrix<double, N, N>;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double condition : {1.0, 1e3, 1e8}) {
    // A = Q diag(lambda) Q^T with eigenvalues spread log-uniformly over [1, condition].
    Matrix random_matrix;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) random_matrix(i, j) = uniform(random);
    const Matrix Q = Eigen::HouseholderQR<Matrix>(random_matrix).householderQ();
    Eigen::Matrix<double, N, 1> eigenvalues;
    for (int i = 0; i < N; ++i) eigenvalues[i] = std::pow(condition, double(i) / (N - 1));
    const Matrix A = Q * eigenvalues.asDiagonal() * Q.transpose();
    const Matrix inverse = positive_definite_inverse<N>(A);
    const Matrix reference = A.fullPivLu().inverse();
    // Both inverses carry a relative error of about eps times the condition number.
    EXPECT_LT((inverse - reference).norm() / reference.norm(), 1e-15 * condition * N) << "N " << N << " cond " << condition;
    EXPECT_LT((A * inverse - Matrix::Identity()).norm(), 1e-15 * condition * N) << "N " << N << " cond " << condition;
    EXPECT_EQ(inverse, inverse.transpose()) << "N " << N;  // L^{-T} L^{-1} is symmetric by construction
  }
}

TEST(PositiveDefiniteInverse, AgreesWithFullPivotingLuOnRandomMatrices) {
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 20; ++trial) {
    check_random_matrices<3>(random);
    check_random_matrices<6>(random);
  }
}

TEST(PositiveDefiniteInverse, IsNaNForAnIndefiniteMatrix) {
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Identity();
  A(4, 4) = -1.0;
  EXPECT_TRUE(positive_definite_inverse<6>(A).array().isNaN().all());
}

}  // namespace
}  // namespace heavesim
