#pragma once
// Complementarity problems with known answers, shared by the tests, the validation checks
// and the peer benchmark (bench/bench_complementarity.cpp): the textbook problems, and
// random problems whose answer is chosen first.
#include <random>

#include "kernel/spatial/types.hpp"

namespace heavesim::samples {

/// An LCP w = M z + q with its answer (when known).
struct LcpSample {
  MatrixX M;
  VectorX q;
  VectorX z;  ///< the answer (the unique one for a P-matrix)
  VectorX w;  ///< M z + q at the answer
};

/// Murty's problem (Murty 1978; Murty 1988, ch. 6): M lower triangular with 1 on the
/// diagonal and 2 below it, q_i = -(2^n + 2^(n-1) + ... + 2^(n+1-i)). M is a P-matrix;
/// the answer is z = (2^n, 0, ..., 0), and Lemke's method with d = 1 takes 2^n pivots
/// to reach it.
LcpSample murty_problem(int n);

/// Random symmetric positive definite LCP: M = B B^T / n + delta I with B uniform in
/// [-1, 1]; the answer is drawn first (about half the rows active, z* in (0, 1] there,
/// w* in (0, 1] elsewhere) and q = w* - M z*.
LcpSample random_spd_lcp(int n, unsigned seed, double delta = 0.1);

/// Random non-symmetric P-matrix LCP: M = B B^T / n + delta I + S with S skew-symmetric
/// (x^T M x = x^T (B B^T / n + delta I) x > 0, so every principal minor is positive);
/// answer chosen first as above.
LcpSample random_p_matrix_lcp(int n, unsigned seed, double delta = 0.1);

/// One impulse step (h = 0.01 s, g = 9.81 m/s^2) of a 1-D stack of n boxes on the ground,
/// masses graded geometrically from 1 kg (bottom) to `top_to_bottom_ratio` kg (top);
/// contact i is under box i. M = J M^-1 J^T is tridiagonal [1/kg], q the approach velocity
/// after gravity (only the ground contact approaches: -g h) [m/s]; the answer is the
/// static impulse through each contact, z_i = h g (m_i + ... + m_n) [N s], with w = 0.
LcpSample box_stack(int n, double top_to_bottom_ratio);

}  // namespace heavesim::samples
