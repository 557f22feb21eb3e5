#include "kernel/complementarity/dantzig.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace heavesim {

DantzigWorkspace::DantzigWorkspace(int size)
    : capacity(size),
      cholesky(size, size),
      clamped_columns(size, size),
      w(size),
      lower(size),
      upper(size),
      direction_z(size),
      direction_w(size),
      gathered(size),
      forward(size),
      inverse_diagonal(size),
      state(size),
      order(size) {
  clamped.reserve(size);
}

namespace {

constexpr double no_limit = std::numeric_limits<double>::infinity();  // a step or room without bound
enum : signed char { undriven = 0, in_clamped = 1, at_lower = 2, at_upper = 3 };

// L y = b in place, L the leading c x c of the lower factor: by columns, each an axpy
// over the rows below (contiguous in the column-major factor). On the ~20-row sets of a
// 50-row problem Eigen's blocked triangular solver spent more in its panel loop than in
// the arithmetic. Both substitutions multiply by the kept reciprocals of L's diagonal: a
// division's latency on the serial chain of the backward pass was the largest single
// cost of a 50-row solve. (Plain scalar loops were 5 % slower than these Eigen segments,
// whose dot products vectorize; a two-column backward pass through Eigen's gemv, 40 %.)
template <typename Vector>
void forward_substitute(const MatrixX& L, const VectorX& inverse_diagonal, int c, Vector&& b) {
  for (int j = 0; j < c; ++j) {
    b[j] *= inverse_diagonal[j];
    b.segment(j + 1, c - j - 1).noalias() -= b[j] * L.col(j).segment(j + 1, c - j - 1);
  }
}
// L^T x = y in place: by columns of L, each a dot product with the rows solved so far.
template <typename Vector>
void backward_substitute(const MatrixX& L, const VectorX& inverse_diagonal, int c, Vector&& y) {
  for (int j = c - 1; j >= 0; --j)
    y[j] = (y[j] - L.col(j).segment(j + 1, c - j - 1).dot(y.segment(j + 1, c - j - 1))) * inverse_diagonal[j];
}

// Appends row j to C: the new row of L is [y^T, sqrt(M_jj - y^T y)] with L y = M_Cj
// (`forward`: y already solved, else null). False if that pivot is not positive (M_CC + j
// singular or indefinite).
bool append_clamped(const ConstMatrixView& M, DantzigWorkspace& ws, int j, double tolerance,
                    const VectorX* forward = nullptr) {
  const int c = static_cast<int>(ws.clamped.size());
  auto y = ws.gathered.head(c);
  if (forward) {
    y = forward->head(c);
  } else {
    for (int k = 0; k < c; ++k) y[k] = M(ws.clamped[k], j);
    forward_substitute(ws.cholesky, ws.inverse_diagonal, c, y);
  }
  const double pivot = M(j, j) - y.squaredNorm();
  if (!(pivot > tolerance * std::abs(M(j, j)))) return false;
  ws.cholesky.row(c).head(c) = y.transpose();
  ws.cholesky(c, c) = std::sqrt(pivot);
  ws.inverse_diagonal[c] = 1.0 / ws.cholesky(c, c);
  ws.clamped_columns.col(c).head(M.rows()) = M.col(j);
  ws.clamped.push_back(j);  // within the reserved capacity
  return true;
}

// Removes position p of C. With L = [L11 0 0; l21 l22 0; L31 l32 L33], the factor of
// M_CC without row/column p is [L11 0; L31 L33'] with L33' L33'^T = L33 L33^T + l32 l32^T:
// a rank-one Cholesky update by Givens-like steps (Gill, Golub, Murray & Saunders 1974).
void remove_clamped(DantzigWorkspace& ws, int p, int n) {
  const int c = static_cast<int>(ws.clamped.size());
  MatrixX& L = ws.cholesky;
  VectorX& x = ws.gathered;
  for (int i = p + 1; i < c; ++i) x[i] = L(i, p);
  for (int k = p + 1; k < c; ++k) {
    const double r = std::hypot(L(k, k), x[k]);
    const double cosine = r / L(k, k), sine = x[k] / L(k, k);
    L(k, k) = r;
    for (int i = k + 1; i < c; ++i) {
      L(i, k) = (L(i, k) + sine * x[i]) / cosine;
      x[i] = cosine * x[i] - sine * L(i, k);
    }
  }
  for (int i = p + 1; i < c; ++i) {
    for (int col = 0; col < p; ++col) L(i - 1, col) = L(i, col);
    for (int col = p + 1; col <= i; ++col) L(i - 1, col - 1) = L(i, col);
  }
  for (int k = p + 1; k < c; ++k) ws.clamped_columns.col(k - 1).head(n) = ws.clamped_columns.col(k).head(n);
  for (int k = p; k + 1 < c; ++k) ws.inverse_diagonal[k] = 1.0 / L(k, k);
  ws.clamped.erase(ws.clamped.begin() + p);
}

}  // namespace

ComplementarityResult dantzig(const ComplementarityProblem& problem, DantzigWorkspace& ws, VectorView z,
                              const DantzigOptions& options) {
  ComplementarityResult result = validate(problem);
  result.solver = ComplementaritySolver::dantzig;
  if (!result.solved()) return result;
  const ConstMatrixView& M = problem.M;
  const int n = problem.size();
  if (!fits_workspace(result, "Dantzig", ws.capacity, n, z.size(), n)) return result;
  const double matrix_scale = n ? M.lpNorm<Eigen::Infinity>() : 0.0;
  for (int j = 0; j < n; ++j) {
    // Column j below the diagonal against row j right of it, a column at a time.
    const int below = n - j - 1;
    Eigen::Index worst = 0;
    if (below == 0 ||
        (M.col(j).tail(below) - M.row(j).tail(below).transpose()).cwiseAbs().maxCoeff(&worst) <= 1e-12 * matrix_scale)
      continue;
    const int i = j + 1 + static_cast<int>(worst);
    result.status = ComplementarityStatus::unsupported;
    result.message = "Dantzig needs a symmetric M; M(" + std::to_string(i) + ", " + std::to_string(j) +
                     ") differs from M(" + std::to_string(j) + ", " + std::to_string(i) + ")";
    return result;
  }
  z.setZero();
  int count = 0;
  for (int i = 0; i < n; ++i) {
    ws.state[i] = undriven;
    if (problem.is_friction_row(i)) continue;
    ws.order[count++] = i;
    ws.lower[i] = problem.lower_bound(i, z);
    ws.upper[i] = problem.upper_bound(i, z);
    if (ws.lower[i] > 0.0 || ws.upper[i] < 0.0) {
      result.status = ComplementarityStatus::unsupported;
      result.message = "Dantzig starts from z = 0, which row " + std::to_string(i) + "'s box excludes";
      return result;
    }
  }
  for (int i = 0; i < n; ++i)
    if (problem.is_friction_row(i)) ws.order[count++] = i;
  ws.clamped.clear();
  ws.w.head(n) = problem.q;
  const double q_scale = n ? problem.q.lpNorm<Eigen::Infinity>() : 0.0;
  const double zero_w = 1e-14 * (q_scale > 0.0 ? q_scale : 1.0);
  result.pivot_limit = options.max_pivots > 0 ? options.max_pivots : 20 * std::max(n, 1);

  auto singular = [&](int row) {
    result.status = ComplementarityStatus::singular_pivot;
    result.message = "Dantzig: pivot of row " + std::to_string(row) +
                     " is not positive (the clamped rows' block of M is singular: redundant or "
                     "duplicate constraints; regularise the diagonal or use another solver)";
    evaluate_residual(problem, z, ws.direction_w.head(n), result);
    return result;
  };

  // A plain LCP's rows are driven in index order, so the rows driven so far are the
  // leading ones: only their w is kept up to date (ODE's dLCP does the same) and a row's
  // w is computed when its drive starts, saving half the products of a solve. Boxed
  // problems keep every w up to date: on the contact step's nearly dependent rows (eight
  // friction directions at four corners of a face) the recomputed and the updated w of a
  // row differ in round-off, and the drive that follows then took another, failing path.
  const bool leading_rows_only = !problem.boxed();
  for (int position = 0; position < n; ++position) {
    const int i = ws.order[position];
    const int live = leading_rows_only ? position + 1 : n;
    if (leading_rows_only) ws.w[i] = problem.q[i] + M.col(i).head(position).dot(z.head(position));
    if (problem.is_friction_row(i)) {
      ws.upper[i] = problem.upper_bound(i, z);
      ws.lower[i] = -ws.upper[i];
    }
    while (true) {
      if (result.pivots >= result.pivot_limit) {
        result.status = ComplementarityStatus::iteration_limit;
        result.message = "Dantzig stopped after " + std::to_string(result.pivots) + " set changes (the cap)";
        evaluate_residual(problem, z, ws.direction_w.head(n), result);
        return result;
      }
      const double w_i = ws.w[i];
      if (std::abs(w_i) <= zero_w) {
        if (z[i] <= ws.lower[i]) ws.state[i] = at_lower;
        else if (z[i] >= ws.upper[i]) ws.state[i] = at_upper;
        else if (!append_clamped(M, ws, i, options.pivot_tolerance)) return singular(i);
        else ws.state[i] = in_clamped;
        break;
      }
      if (w_i > 0.0 && z[i] <= ws.lower[i]) { ws.state[i] = at_lower; break; }
      if (w_i < 0.0 && z[i] >= ws.upper[i]) { ws.state[i] = at_upper; break; }
      const double s = w_i < 0.0 ? 1.0 : -1.0;
      // dz_C = -s M_CC^-1 M_Ci keeps w_C = 0; dw = M_:C dz_C + s M_:i.
      const int c = static_cast<int>(ws.clamped.size());
      auto v = ws.gathered.head(c);
      for (int k = 0; k < c; ++k) v[k] = M(ws.clamped[k], i);
      forward_substitute(ws.cholesky, ws.inverse_diagonal, c, v);
      ws.forward.head(c) = v;  // L^-1 M_Ci: the new row of L if i joins C at the end of this step
      backward_substitute(ws.cholesky, ws.inverse_diagonal, c, v);
      // Only the rows driven so far (and i) need their w: the others' w is computed when
      // their own drive starts.
      auto direction_w = ws.direction_w.head(live);
      v *= -s;  // dz_C
      direction_w = s * M.col(i).head(live);
      direction_w.noalias() += ws.clamped_columns.topLeftCorner(live, c) * v;
      for (int k = 0; k < c; ++k) ws.direction_z[ws.clamped[k]] = v[k];
      const double dw_i = ws.direction_w[i];
      // w_i that does not move with z_i (row i depends on the clamped rows: a friction
      // row along a coordinate a driver holds) cannot be driven to zero; a boxed row then
      // goes to its bound (or until another set changes), a free row is singular.
      const bool w_stays = !(s * dw_i > options.pivot_tolerance * std::abs(M(i, i)));
      // The longest step before a set changes.
      double step = w_stays ? no_limit : -w_i / dw_i;
      int limiting = i;
      bool limit_is_bound = false;
      const double own_room = s > 0.0 ? ws.upper[i] - z[i] : z[i] - ws.lower[i];
      if (own_room < step) step = own_room, limit_is_bound = true;
      for (int k = 0; k < c; ++k) {
        const int j = ws.clamped[k];
        const double dz = ws.direction_z[j];
        const double room = dz > 0.0 ? (ws.upper[j] - z[j]) / dz : dz < 0.0 ? (ws.lower[j] - z[j]) / dz : no_limit;
        if (room < step) step = room, limiting = j, limit_is_bound = true;
      }
      for (int j = 0; j < live; ++j) {
        const double dw = ws.direction_w[j];
        if ((ws.state[j] == at_lower && dw < 0.0) || (ws.state[j] == at_upper && dw > 0.0)) {
          const double room = -ws.w[j] / dw;
          if (room < step) step = room, limiting = j, limit_is_bound = false;
        }
      }
      if (!std::isfinite(step)) return singular(i);
      step = std::max(step, 0.0);
      z[i] += s * step;
      for (int k = 0; k < c; ++k) z[ws.clamped[k]] += step * ws.direction_z[ws.clamped[k]];
      ws.w.head(live) += step * direction_w;
      for (int k = 0; k < c; ++k) ws.w[ws.clamped[k]] = 0.0;
      ++result.pivots;
      if (limiting == i) {
        if (limit_is_bound) {
          z[i] = s > 0.0 ? ws.upper[i] : ws.lower[i];
          ws.state[i] = s > 0.0 ? at_upper : at_lower;
        } else {
          ws.w[i] = 0.0;
          if (!append_clamped(M, ws, i, options.pivot_tolerance, &ws.forward)) return singular(i);
          ws.state[i] = in_clamped;
        }
        break;
      }
      if (limit_is_bound) {  // a clamped row reached a bound: it leaves C
        const int k = static_cast<int>(std::find(ws.clamped.begin(), ws.clamped.end(), limiting) - ws.clamped.begin());
        z[limiting] = ws.direction_z[limiting] > 0.0 ? ws.upper[limiting] : ws.lower[limiting];
        ws.state[limiting] = ws.direction_z[limiting] > 0.0 ? at_upper : at_lower;
        remove_clamped(ws, k, n);
      } else {  // a row at a bound reached w = 0: it joins C
        ws.w[limiting] = 0.0;
        if (!append_clamped(M, ws, limiting, options.pivot_tolerance)) return singular(limiting);
        ws.state[limiting] = in_clamped;
      }
    }
  }
  evaluate_residual(problem, z, ws.direction_w.head(n), result);
  result.status = result.residual <= options.tolerance ? ComplementarityStatus::solved
                                                       : ComplementarityStatus::not_converged;
  if (!result.solved())
    result.message = "Dantzig ended with relative residual " + std::to_string(result.residual) +
                     (problem.has_friction() ? " (friction boxes frozen before the normal values settled)" : "");
  return result;
}

}  // namespace heavesim
