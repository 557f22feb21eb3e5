#pragma once
// Solves S x = b for a symmetric positive semi-definite S -- the Schur complement
// J M^-1 J^T of the constraint equations -- that may be singular (redundant rows) or
// nearly so (a singular configuration), by Cholesky of the regularized matrix
//   (S + epsilon I) x = b,   epsilon = relative_regularization * max diag(S).
// On the eigenvectors of S this is x = sum (u^T b) / (sigma + epsilon) u: for b in the
// range of S, the minimum-norm solution up to a relative error epsilon / sigma (1e-12
// for the multipliers), and a smooth fade-out of directions whose eigenvalue is near
// or below epsilon instead of a switch. Allocation-free once sized (an eigen- or
// orthogonal decomposition would allocate inside Eigen on every call).
#include "kernel/math/sized_cholesky.hpp"

namespace heavesim {

class RegularizedSymmetricSolver {
 public:
  explicit RegularizedSymmetricSolver(int size = 0) : regularized_(MatrixX::Zero(size, size)), cholesky_(size) {}

  void compute(const MatrixX& S, double relative_regularization) {
    regularized_ = S;
    const double epsilon = relative_regularization * std::max(S.diagonal().maxCoeff(), 0.0);
    regularized_.diagonal().array() += epsilon > 0.0 ? epsilon : 1.0;  // S = 0: any positive shift gives x = 0
    cholesky_.compute(regularized_);
  }

  /// x = (S + epsilon I)^-1 b.
  void solve(const VectorX& b, VectorX& x) const {
    x = b;
    cholesky_.solveInPlace(x);
  }

 private:
  MatrixX regularized_;
  SizedCholesky cholesky_;
};

}  // namespace heavesim
