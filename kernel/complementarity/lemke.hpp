#pragma once
// Lemke's complementary pivoting method (Lemke 1965; Cottle, Pang & Stone 1992, 4.4;
// Murty 1988, ch. 2) for LCP(M, q), and for boxed MLCPs with fixed bounds through the
// LCP of twice the size (docs/physics/complementarity.md).
//
// The tableau w - M z - d z0 = q is kept as the explicit inverse of the basis, B^-1
// (n x n), updated by one rank-one (product-form) step per pivot: O(n^2) a pivot, against
// the O(n^3) of a lexicographic test that re-solves the basis (Bullet's btLemkeAlgorithm).
// The lexicographic minimum-ratio rule reads the rows of B^-1 directly, so degenerate
// ties cannot cycle. At termination one step of iterative refinement with the original
// columns restores the accuracy lost to the updates.
#include <vector>

#include "kernel/complementarity/complementarity_problem.hpp"

namespace heavesim {

/// A variable of Lemke's tableau: w_i, z_i (0-based) or the covering variable z0.
struct LemkeVariable {
  enum Kind { w, z, covering } kind;
  int index = 0;
  bool operator==(const LemkeVariable&) const = default;
};

/// One pivot: the variable that entered the basis and the one that left.
struct LemkePivot {
  LemkeVariable entering;
  LemkeVariable leaving;
  bool operator==(const LemkePivot&) const = default;
};

/// How a tie in the minimum-ratio test is broken.
enum class LemkeTieBreak {
  lexicographic,  ///< the lexicographic minimum of the tied rows of [B^-1 q, B^-1] / a: never cycles
  first_row,      ///< the first tied row of the tableau: the textbook rule, which can cycle (kept to show that it does)
};

struct LemkeOptions {
  /// Covering vector d (all entries > 0); null: d = 1. Size: the LCP Lemke solves (n, or
  /// n + the finite upper bounds for a boxed problem).
  const VectorX* covering_vector = nullptr;
  /// Pivot cap; 0: max(50 N, 1000) for an LCP of size N. Murty's problem needs 2^N.
  int max_pivots = 0;
  LemkeTieBreak tie_break = LemkeTieBreak::lexicographic;
  /// Relative tolerance of the ratio test: entries of the entering column at most this
  /// times its largest entry do not block, and ratios this close (relatively) tie.
  double zero_tolerance = 1e-12;
  /// The answer counts as solved when the relative residual is at most this.
  double tolerance = 1e-10;
  /// If not null, every pivot is appended (reserve it to keep the solve allocation-free).
  std::vector<LemkePivot>* pivot_log = nullptr;
};

/// Buffers for problems of up to `size` rows (boxed: up to 2 size), sized once.
struct LemkeWorkspace {
  explicit LemkeWorkspace(int size = 0);
  int capacity = 0;  ///< the largest LCP (after the box expansion) it holds
  MatrixX basis_inverse;
  MatrixX expanded_matrix;  ///< boxed problems: [[M, E], [-E^T, 0]]
  VectorX expanded_vector, basic_values, column, pivot_row, covering, refinement, w;
  std::vector<int> basis;        ///< variable code of each tableau row (0..N-1 w, N..2N-1 z, 2N z0)
  std::vector<int> row_of;       ///< tableau row of each variable code, -1 if non-basic
  std::vector<int> ties, bounded_rows;
};

/// Solves the problem by Lemke's method; z (size n) receives the answer (left as is on
/// failure other than iteration_limit / ray_termination, where it holds the last basis).
/// Rows must have a finite lower bound (lo = 0 for the LCP); friction rows are refused
/// (status unsupported: their bounds depend on z).
ComplementarityResult lemke(const ComplementarityProblem& problem, LemkeWorkspace& workspace, VectorView z,
                            const LemkeOptions& options = {});

}  // namespace heavesim
