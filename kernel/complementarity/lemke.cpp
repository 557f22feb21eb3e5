#include "kernel/complementarity/lemke.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace heavesim {

LemkeWorkspace::LemkeWorkspace(int size)
    : capacity(2 * size),
      basis_inverse(2 * size, 2 * size),
      expanded_matrix(2 * size, 2 * size),
      expanded_vector(2 * size),
      basic_values(2 * size),
      column(2 * size),
      pivot_row(2 * size),
      covering(2 * size),
      refinement(2 * size),
      w(size),
      basis(2 * size),
      row_of(4 * size + 1),
      ties(2 * size),
      bounded_rows(size) {}

namespace {

// The LCP Lemke works on: w = A z + b of size N (the problem itself, or its box expansion).
struct Tableau {
  const ConstMatrixView& A;
  const ConstVectorView& b;
  int N;
  int covering_code() const { return 2 * N; }
  LemkeVariable variable(int code) const {
    if (code < N) return {LemkeVariable::w, code};
    if (code < 2 * N) return {LemkeVariable::z, code - N};
    return {LemkeVariable::covering, 0};
  }
};

// column = B^-1 * (the tableau column of variable `code`): w_j -> e_j, z_j -> -A_j, z0 -> -d.
void entering_column(const Tableau& t, LemkeWorkspace& ws, int code) {
  auto column = ws.column.head(t.N);
  const auto Binv = ws.basis_inverse.topLeftCorner(t.N, t.N);
  if (code < t.N) {
    column = Binv.col(code);
  } else if (code < 2 * t.N) {
    column.noalias() = Binv * t.A.col(code - t.N).head(t.N);
    column = -column;
  } else {
    column.noalias() = Binv * ws.covering.head(t.N);
    column = -column;
  }
}

// The row that leaves when the variable with column ws.column enters: the minimum ratio
// basic_value / column over the blocking rows; -1 if none blocks (ray termination).
int ratio_test(const Tableau& t, LemkeWorkspace& ws, const LemkeOptions& options) {
  const int N = t.N;
  const auto a = ws.column.head(N);
  const auto x = ws.basic_values.head(N);
  const double blocking = options.zero_tolerance * std::max(a.lpNorm<Eigen::Infinity>(), 1e-300);
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < N; ++i)
    if (a[i] > blocking) smallest = std::min(smallest, std::max(x[i], 0.0) / a[i]);
  if (smallest == std::numeric_limits<double>::infinity()) return -1;
  const double tie = options.zero_tolerance * std::max(1.0, smallest);
  int count = 0;
  for (int i = 0; i < N; ++i)
    if (a[i] > blocking && std::max(x[i], 0.0) / a[i] <= smallest + tie) ws.ties[count++] = i;
  if (count == 1) return ws.ties[0];
  // z0 among the ties: let it leave, which ends the method with a solution (Cottle,
  // Pang & Stone 1992, 4.4).
  const int covering_row = ws.row_of[t.covering_code()];
  for (int k = 0; k < count; ++k)
    if (ws.ties[k] == covering_row) return covering_row;
  if (options.tie_break == LemkeTieBreak::first_row) return ws.ties[0];
  // Lexicographic minimum of the rows of B^-1 divided by a_i, column by column: the
  // rows of [B^-1 q, B^-1] stay lexicographically positive, so no basis repeats.
  const auto Binv = ws.basis_inverse.topLeftCorner(N, N);
  for (int k = 0; k < N && count > 1; ++k) {
    double least = std::numeric_limits<double>::infinity();
    for (int m = 0; m < count; ++m) least = std::min(least, Binv(ws.ties[m], k) / a[ws.ties[m]]);
    const double close = options.zero_tolerance * std::max(1.0, std::abs(least));
    int kept = 0;
    for (int m = 0; m < count; ++m)
      if (Binv(ws.ties[m], k) / a[ws.ties[m]] <= least + close) ws.ties[kept++] = ws.ties[m];
    count = kept;
  }
  return ws.ties[0];
}

// Gauss-Jordan pivot on row r of the column in ws.column: B^-1 <- E B^-1, x <- E x.
void pivot(const Tableau& t, LemkeWorkspace& ws, int r, int entering_code) {
  const int N = t.N;
  auto a = ws.column.head(N);
  auto Binv = ws.basis_inverse.topLeftCorner(N, N);
  auto x = ws.basic_values.head(N);
  const double pivot_value = a[r];
  auto row = ws.pivot_row.head(N);
  row = Binv.row(r).transpose() / pivot_value;
  const double x_r = x[r] / pivot_value;
  a[r] = 0.0;  // row r is replaced below, not updated
  Binv.noalias() -= a * row.transpose();
  x -= a * x_r;
  Binv.row(r) = row.transpose();
  x[r] = x_r;
  ws.row_of[ws.basis[r]] = -1;
  ws.basis[r] = entering_code;
  ws.row_of[entering_code] = r;
}

std::string variable_name(const LemkeVariable& v) {
  if (v.kind == LemkeVariable::covering) return "z0";
  return std::string(v.kind == LemkeVariable::w ? "w" : "z") + "(" + std::to_string(v.index) + ")";
}

void log_pivot(const Tableau& t, const LemkeOptions& options, int entering, int leaving) {
  if (options.pivot_log) options.pivot_log->push_back({t.variable(entering), t.variable(leaving)});
}

// One step of iterative refinement: x += B^-1 (b - B x), with B's columns taken from A.
void refine(const Tableau& t, LemkeWorkspace& ws) {
  const int N = t.N;
  auto r = ws.refinement.head(N);
  r = t.b.head(N);
  for (int i = 0; i < N; ++i) {
    const int code = ws.basis[i];
    const double value = ws.basic_values[i];
    if (code < N) r[code] -= value;
    else if (code < 2 * N) r += value * t.A.col(code - N).head(N);
    else r += value * ws.covering.head(N);
  }
  ws.basic_values.head(N).noalias() += ws.basis_inverse.topLeftCorner(N, N) * r;
}

}  // namespace

ComplementarityResult lemke(const ComplementarityProblem& problem, LemkeWorkspace& ws, VectorView z,
                            const LemkeOptions& options) {
  ComplementarityResult result = validate(problem);
  result.solver = ComplementaritySolver::lemke;
  if (!result.solved()) return result;
  const int n = problem.size();
  // The box expansion: z = lo + s, s >= 0, and for each finite hi a variable y >= 0
  // complementary to hi - lo - s >= 0 (Cottle, Pang & Stone 1992, 1.5):
  //   [w_s]   [ M   E] [s]   [q + M lo]
  //   [w_y] = [-E^T 0] [y] + [(hi - lo)_E],   w = w_s - E y.
  int bounded = 0;
  if (problem.boxed()) {
    for (int i = 0; i < n; ++i) {
      if (problem.is_friction_row(i)) {
        result.status = ComplementarityStatus::unsupported;
        result.message = "Lemke takes fixed bounds only; row " + std::to_string(i) +
                         " is a friction row whose bounds scale with its normal row";
        return result;
      }
      if (!std::isfinite(problem.lower_bound(i, z))) {
        result.status = ComplementarityStatus::unsupported;
        result.message = "Lemke needs a finite lower bound; row " + std::to_string(i) + " has none";
        return result;
      }
      if (std::isfinite(problem.upper_bound(i, z))) ws.bounded_rows[bounded++] = i;
    }
  }
  const int N = n + bounded;
  if (!fits_workspace(result, "Lemke", ws.capacity, N, z.size(), n)) return result;
  if (options.covering_vector &&
      (options.covering_vector->size() != N || !(options.covering_vector->minCoeff() > 0.0) ||
       !options.covering_vector->allFinite())) {
    result.status = ComplementarityStatus::invalid_input;
    result.message = "covering vector d needs " + std::to_string(N) + " finite entries > 0";
    return result;
  }
  if (problem.boxed()) {
    auto A = ws.expanded_matrix.topLeftCorner(N, N);
    A.setZero();
    A.topLeftCorner(n, n) = problem.M;
    auto b = ws.expanded_vector.head(N);
    for (int i = 0; i < n; ++i) z[i] = problem.lower_bound(i, z);
    b.head(n).noalias() = problem.M * z;
    b.head(n) += problem.q;
    for (int k = 0; k < bounded; ++k) {
      const int i = ws.bounded_rows[k];
      A(i, n + k) = 1.0;
      A(n + k, i) = -1.0;
      b[n + k] = problem.upper_bound(i, z) - z[i];
    }
  }
  // Views of the LCP solved: the problem itself, or the expansion in the workspace
  // (whose first N x N block is used).
  const ConstMatrixView A = problem.boxed() ? ConstMatrixView(ws.expanded_matrix) : problem.M;
  const ConstVectorView b = problem.boxed() ? ConstVectorView(ws.expanded_vector) : problem.q;
  const Tableau t{A, b, N};
  if (options.covering_vector) ws.covering.head(N) = *options.covering_vector;
  else ws.covering.head(N).setOnes();
  result.pivot_limit = options.max_pivots > 0 ? options.max_pivots : std::max(50 * N, 1000);

  auto finish = [&](ComplementarityStatus status) {
    for (int i = 0; i < n; ++i) {
      const int row = ws.row_of[N + i];
      const double s = row >= 0 ? std::max(ws.basic_values[row], 0.0) : 0.0;
      z[i] = (problem.boxed() ? problem.lower_bound(i, z) : 0.0) + s;
    }
    evaluate_residual(problem, z, ws.w.head(n), result);
    result.status = status;
    if (status == ComplementarityStatus::solved && !(result.residual <= options.tolerance)) {
      result.status = ComplementarityStatus::not_converged;
      result.message = "Lemke ended with relative residual " + std::to_string(result.residual) +
                       " above the tolerance";
    }
    return result;
  };

  // Start: the basis of the w's, B^-1 = I, x = b.
  ws.basis_inverse.topLeftCorner(N, N).setIdentity();
  ws.basic_values.head(N) = b.head(N);
  std::fill(ws.row_of.begin(), ws.row_of.begin() + 2 * N + 1, -1);
  for (int i = 0; i < N; ++i) ws.basis[i] = i, ws.row_of[i] = i;
  if (b.head(N).minCoeff() >= 0.0) return finish(ComplementarityStatus::solved);  // z = lo is the answer

  // z0 enters at the level that makes every w nonnegative, z0 = max(-b_i / d_i): that
  // row leaves. After the pivot the rows of [x, B^-1] must stay lexicographically
  // nonnegative, so among tied rows the least of [b_i, e_i] / d_i leaves: the last tied
  // row, whose unit entry comes latest (the first-row rule takes the first).
  int entering = t.covering_code();
  {
    double largest = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < N; ++i) largest = std::max(largest, -b[i] / ws.covering[i]);
    const double tie = options.zero_tolerance * std::max(1.0, std::abs(largest));
    int count = 0;
    for (int i = 0; i < N; ++i)
      if (-b[i] / ws.covering[i] >= largest - tie) ws.ties[count++] = i;
    const int r = options.tie_break == LemkeTieBreak::lexicographic ? ws.ties[count - 1] : ws.ties[0];
    ws.column.head(N) = -ws.covering.head(N);
    pivot(t, ws, r, entering);
    result.pivots = 1;
    log_pivot(t, options, entering, r);
    entering = r + N;  // the complement of w_r
  }
  while (true) {
    if (result.pivots >= result.pivot_limit) {
      result.message = "Lemke stopped after " + std::to_string(result.pivots) +
                       " pivots (the cap; set max_pivots for problems such as Murty's that need 2^n)";
      return finish(ComplementarityStatus::iteration_limit);
    }
    entering_column(t, ws, entering);
    const int r = ratio_test(t, ws, options);
    if (r < 0) {
      result.message = "Lemke: ray termination with " + variable_name(t.variable(entering)) +
                       " entering (no solution if M is copositive-plus; otherwise outside the method's class)";
      return finish(ComplementarityStatus::ray_termination);
    }
    const int leaving = ws.basis[r];
    pivot(t, ws, r, entering);
    ++result.pivots;
    log_pivot(t, options, entering, leaving);
    if (leaving == t.covering_code()) break;
    entering = leaving < N ? leaving + N : leaving - N;
  }
  refine(t, ws);
  return finish(ComplementarityStatus::solved);
}

}  // namespace heavesim
