#pragma once
// The minimum-norm solution, in a metric W = L L^T (the mass matrix: minimum kinetic
// energy; or the identity), of the linear constraint equations J x = b, for a J whose
// rows may depend on one another (redundant constraints):
//   x = W^-1 J^T y,   (J W^-1 J^T) y = b.
// With A = J L^-T the problem is min |L^T x| subject to A (L^T x) = b, whose answer is
// L^T x = A^T (A A^T)^+ b. A column-pivoted Householder QR of A^T (A^T P = Q R) reveals
// the rank r and which rows of J are independent (the first r pivots); y is taken on those
// rows only (R11^T R11 y1 = (P^T b)_1, the rest 0). Any solution y gives the same x
// (J^T y is unique: null(J W^-1 J^T) = null(J^T)), so x is the exact W-minimum-norm
// solution whenever b is consistent, and the basic least-squares one of the independent
// rows otherwise. Unlike forming J W^-1 J^T, the QR works on A itself: its pivots scale
// with the singular values of A, not their squares, so the rank is resolved to a
// relative 1e-10 (Golub & Van Loan, Matrix Computations, 4th ed., 5.4.2; Haug 1989,
// 3.7 for the same idea on the Jacobian).
// Allocation-free once sized: the QR keeps its storage (the constructor preallocates),
// and the solve uses only triangular views and loops.
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "kernel/spatial/types.hpp"

namespace heavesim {

class MinimumNormSolver {
 public:
  /// For J of `rows` x `columns` (m x nv).
  explicit MinimumNormSolver(int columns = 0, int rows = 0)
      : scaled_transpose_(MatrixX::Zero(columns, rows)),
        qr_(columns, rows),
        permuted_(VectorX::Zero(rows)) {}

  /// Factorizes J (m x nv) in the metric whose Cholesky factor is `metric` (W = L L^T);
  /// null: the identity. Rows whose QR pivot is at most `rank_threshold` times the
  /// largest count as depending on the others.
  void factorize(const MatrixX& jacobian, const Eigen::LLT<MatrixX>* metric, double rank_threshold) {
    metric_ = metric;
    scaled_transpose_ = jacobian.transpose();
    if (metric_) metric_->matrixL().solveInPlace(scaled_transpose_);  // A^T = L^-1 J^T
    qr_.setThreshold(rank_threshold);
    qr_.compute(scaled_transpose_);
    rank_ = jacobian.rows() == 0 ? 0 : static_cast<int>(qr_.rank());
  }

  /// x (nv) = the W-minimum-norm solution of J x = b (b: m).
  void solve(const VectorX& b, VectorX& x) {
    const int rows = static_cast<int>(permuted_.size());
    x.setZero();
    if (rank_ == 0) return;
    const auto& indices = qr_.colsPermutation().indices();
    for (int k = 0; k < rows; ++k) permuted_[k] = b[indices[k]];
    auto head = permuted_.head(rank_);
    const auto R11 = qr_.matrixQR().topLeftCorner(rank_, rank_).template triangularView<Eigen::Upper>();
    R11.transpose().solveInPlace(head);
    R11.solveInPlace(head);
    // L^T x = A^T P [y1; 0]: the independent columns of A^T, combined.
    for (int k = 0; k < rank_; ++k) x.noalias() += permuted_[k] * scaled_transpose_.col(indices[k]);
    if (metric_) metric_->matrixU().solveInPlace(x);  // x = L^-T (L^T x)
  }

  /// Rank of J (number of independent rows).
  int rank() const { return rank_; }
  /// |R_kk| / |R_00| of the pivoted QR of A^T: how close row set {0..k} of the pivot
  /// order is to dependent (an estimate of sigma_k / sigma_0 of A within a factor that
  /// depends only on the size; 0 when k is beyond the rows).
  double pivot_ratio(int k) const {
    const int size = static_cast<int>(std::min(qr_.matrixQR().rows(), qr_.matrixQR().cols()));
    if (k < 0 || k >= size) return 0.0;
    const double largest = std::abs(qr_.matrixQR()(0, 0));
    return largest > 0.0 ? std::abs(qr_.matrixQR()(k, k)) / largest : 0.0;
  }
  /// Row of J at pivot position k (the first rank() are the independent ones).
  int pivot_row(int k) const { return qr_.colsPermutation().indices()[k]; }
  /// A^T = L^-1 J^T of the last factorization (nv x m).
  const MatrixX& scaled_jacobian_transpose() const { return scaled_transpose_; }
  /// Copies the triangular factor R of A^T P = Q R (its top min(nv, m) rows, below the
  /// diagonal zeroed) into `triangle` (sized min(nv, m) x m by the caller): R has the
  /// singular values of A, as Q is orthogonal and P a permutation, on a smaller matrix.
  void triangular_factor(MatrixX& triangle) const {
    triangle = qr_.matrixQR().topRows(triangle.rows()).template triangularView<Eigen::Upper>();
  }

 private:
  MatrixX scaled_transpose_;
  Eigen::ColPivHouseholderQR<MatrixX> qr_;
  VectorX permuted_;
  const Eigen::LLT<MatrixX>* metric_ = nullptr;
  int rank_ = 0;
};

}  // namespace heavesim
