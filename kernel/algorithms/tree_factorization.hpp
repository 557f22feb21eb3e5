#pragma once
// The L^T L factorization of the joint-space inertia matrix that keeps the tree's
// branch-induced sparsity (Featherstone 2008, sec. 6.5, tables 6.3 and 6.4; Featherstone
// 2005, "Efficient factorization of the joint-space inertia matrix for branched kinematic
// trees"). M(i, j) is nonzero only when velocity coordinate i is an ancestor of j or j of
// i; factoring from the leaves up (M = L^T L, L lower triangular) creates no other
// entries, so a factor and a solve cost the sum of the coordinates' depths instead of
// n^3 / 3 and n^2: for k free bodies, k times 6 x 6 work instead of (6k)^2. The dense
// Cholesky (mass_matrix.hpp) stays the general path; this one serves solves with many
// right-hand sides on wide trees (contact stepping: M^-1 J^T).
#include <vector>

#include "kernel/model/model.hpp"

namespace heavesim {

/// Overwrites the lower triangle of `factor` (n x n, holding M's lower triangle on entry)
/// with L such that M = L^T L. Reads and writes only the entries (i, j) with j an
/// ancestor-or-self of i. False (factor partly overwritten) if a pivot is not positive:
/// M is not positive definite. Allocation-free.
bool factorize_tree(const std::vector<int>& parent, MatrixX& factor);

/// x <- M^-1 x = L^-1 L^-T x with the factor of factorize_tree. Allocation-free.
void solve_tree(const std::vector<int>& parent, const MatrixX& factor, Eigen::Ref<VectorX> x);

}  // namespace heavesim
