#pragma once
// The inverse of a small symmetric positive definite matrix of fixed size N through its
// Cholesky factor: A = L L^T, so A^{-1} = L^{-T} L^{-1}, with L^{-1} by forward substitution
// (Golub and Van Loan, Matrix Computations, 4th ed., sec. 4.2 and 3.1). Eigen's
// LLT::solve(Identity) gives the same matrix, but a matrix right-hand side goes through its
// blocked triangular solver (trsm) even at fixed size: 8 % of a free floating platform's
// 3-hour run, in the free joint's articulated-body step (which, for a free joint on the
// world, now solves with the Cholesky factor instead: no inverse needed there). ABA still
// needs D^-1 for a free joint below another body. Here every loop has fixed bounds.
// A matrix that is not positive definite (numerically) gives NaN in every entry: Eigen's
// solve would return a finite matrix built on the factorization's partial result, and the
// caller's check for non-finite accelerations would not see it.
#include <limits>

#include <Eigen/Cholesky>

namespace heavesim {

template <int N>
Eigen::Matrix<double, N, N> positive_definite_inverse(const Eigen::Matrix<double, N, N>& matrix) {
  const Eigen::LLT<Eigen::Matrix<double, N, N>> cholesky(matrix);
  if (cholesky.info() != Eigen::Success)
    return Eigen::Matrix<double, N, N>::Constant(std::numeric_limits<double>::quiet_NaN());
  const Eigen::Matrix<double, N, N>& factor = cholesky.matrixLLT();  // L in the lower triangle
  Eigen::Matrix<double, N, N> inverse_factor = Eigen::Matrix<double, N, N>::Zero();  // L^{-1}
  for (int j = 0; j < N; ++j) {
    inverse_factor(j, j) = 1.0 / factor(j, j);
    for (int i = j + 1; i < N; ++i) {
      double sum = 0.0;
      for (int k = j; k < i; ++k) sum += factor(i, k) * inverse_factor(k, j);
      inverse_factor(i, j) = -sum / factor(i, i);
    }
  }
  return inverse_factor.transpose().lazyProduct(inverse_factor);
}

}  // namespace heavesim
