#include "kernel/algorithms/tree_factorization.hpp"

#include <cmath>

namespace heavesim {

// Featherstone 2008, table 6.3: from the last coordinate to the first, take the square
// root of the pivot, scale the row's ancestors, and subtract the outer product from the
// ancestors' block (only ancestor pairs are touched: no fill-in).
bool factorize_tree(const std::vector<int>& parent, MatrixX& H) {
  const int n = static_cast<int>(parent.size());
  for (int k = n - 1; k >= 0; --k) {
    if (!(H(k, k) > 0.0)) return false;
    H(k, k) = std::sqrt(H(k, k));
    for (int i = parent[k]; i >= 0; i = parent[i]) H(k, i) /= H(k, k);
    for (int i = parent[k]; i >= 0; i = parent[i])
      for (int j = i; j >= 0; j = parent[j]) H(i, j) -= H(k, i) * H(k, j);
  }
  return true;
}

// Table 6.4: x <- L^-T x (from the leaves up: each coordinate feeds its ancestors), then
// x <- L^-1 x (from the root down).
void solve_tree(const std::vector<int>& parent, const MatrixX& L, Eigen::Ref<VectorX> x) {
  const int n = static_cast<int>(parent.size());
  for (int i = n - 1; i >= 0; --i) {
    x[i] /= L(i, i);
    if (x[i] == 0.0) continue;  // a sparse right-hand side (a contact row's chain) stays sparse
    for (int j = parent[i]; j >= 0; j = parent[j]) x[j] -= L(i, j) * x[i];
  }
  for (int i = 0; i < n; ++i) {
    for (int j = parent[i]; j >= 0; j = parent[j]) x[i] -= L(i, j) * x[j];
    x[i] /= L(i, i);
  }
}

}  // namespace heavesim
