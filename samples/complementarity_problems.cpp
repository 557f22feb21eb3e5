#include "samples/complementarity_problems.hpp"

#include <cmath>

namespace heavesim::samples {

LcpSample murty_problem(int n) {
  LcpSample sample;
  sample.M = MatrixX::Identity(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j) sample.M(i, j) = 2.0;
  sample.q.resize(n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sum += std::ldexp(1.0, n - i);  // 2^n, 2^(n-1), ...
    sample.q[i] = -sum;
  }
  sample.z = VectorX::Zero(n);
  sample.z[0] = std::ldexp(1.0, n);
  sample.w = sample.M * sample.z + sample.q;
  return sample;
}

namespace {
LcpSample with_chosen_answer(MatrixX M, std::mt19937& random) {
  const int n = static_cast<int>(M.rows());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  LcpSample sample;
  sample.z = VectorX::Zero(n);
  sample.w = VectorX::Zero(n);
  for (int i = 0; i < n; ++i) {
    const double value = 1.0 - unit(random);  // (0, 1]
    (unit(random) < 0.5 ? sample.z[i] : sample.w[i]) = value;
  }
  sample.q = sample.w - M * sample.z;
  sample.M = std::move(M);
  return sample;
}

MatrixX random_gram(int n, std::mt19937& random, double delta) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  MatrixX B(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) B(i, j) = entry(random);
  MatrixX M = B * B.transpose() / n;
  M.diagonal().array() += delta;
  return M;
}
}  // namespace

LcpSample random_spd_lcp(int n, unsigned seed, double delta) {
  std::mt19937 random(seed);
  MatrixX M = random_gram(n, random, delta);
  return with_chosen_answer(std::move(M), random);
}

LcpSample random_p_matrix_lcp(int n, unsigned seed, double delta) {
  std::mt19937 random(seed);
  MatrixX M = random_gram(n, random, delta);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < j; ++i) {
      const double s = entry(random);
      M(i, j) += s;
      M(j, i) -= s;
    }
  return with_chosen_answer(std::move(M), random);
}

LcpSample box_stack(int n, double top_to_bottom_ratio) {
  const double g = 9.81, h = 0.01;
  VectorX mass(n);
  for (int k = 0; k < n; ++k) mass[k] = n > 1 ? std::pow(top_to_bottom_ratio, double(k) / (n - 1)) : 1.0;
  LcpSample stack{MatrixX::Zero(n, n), VectorX::Zero(n), VectorX::Zero(n), VectorX::Zero(n)};
  for (int i = 0; i < n; ++i) {
    stack.M(i, i) = 1.0 / mass[i] + (i > 0 ? 1.0 / mass[i - 1] : 0.0);
    if (i > 0) stack.M(i, i - 1) = stack.M(i - 1, i) = -1.0 / mass[i - 1];
  }
  stack.q[0] = -g * h;
  for (int i = n - 1; i >= 0; --i) stack.z[i] = h * g * mass[i] + (i + 1 < n ? stack.z[i + 1] : 0.0);
  return stack;
}

}  // namespace heavesim::samples
