#include "hydro/radiation/state_space.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {

void check_state_space_order(int order) {
  // One state cannot hold the oscillation of a radiation kernel; more than the fixed
  // maximum would not fit the element's pre-sized state matrices.
  if (order < 2 || order > max_state_space_order)
    throw ParameterError("state_space_order", fmt::format("{}", order),
                         fmt::format("a state-space order in 2 .. {}", max_state_space_order));
}

namespace {

// Above this condition number of the eigenvector basis the change of basis could lose
// more than ~1e-10 of the kernel (the round-off of V^-1 B and C V grows as cond(V) eps).
constexpr double largest_modal_condition = 1e6;

}  // namespace

bool to_modal_form(ModePairStateSpace& system) {
  const Eigen::MatrixXd A = system.A;
  if (A.rows() == 0) return false;
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(A);
  if (eigen.info() != Eigen::Success) return false;
  // A V = V D, D block diagonal: a 1 x 1 block per real eigenvalue, a 2 x 2 block
  // [[a, b], [-b, a]] per pair a +- i b (Eigen's pseudo-eigendecomposition).
  Eigen::MatrixXd V = eigen.pseudoEigenvectors();
  const Eigen::MatrixXd D = eigen.pseudoEigenvalueMatrix();
  // Each block's columns scaled to unit size together: a common factor keeps the
  // block's form and takes the arbitrary lengths of the eigenvectors out of cond(V).
  const Eigen::Index n = A.rows();
  for (Eigen::Index k = 0; k < n;) {
    const Eigen::Index width = k + 1 < n && D(k + 1, k) != 0.0 ? 2 : 1;
    const double size = V.middleCols(k, width).norm();
    if (!(size > 0.0)) return false;
    V.middleCols(k, width) /= width == 2 ? size / std::numbers::sqrt2 : size;  // columns of length ~1
    k += width;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> singular(V);
  const Eigen::VectorXd& sigma = singular.singularValues();
  if (!(sigma[n - 1] > 0.0) || sigma[0] / sigma[n - 1] > largest_modal_condition) return false;
  const Eigen::PartialPivLU<Eigen::MatrixXd> basis(V);
  system.B = basis.solve(Eigen::VectorXd(system.B));
  system.C = Eigen::RowVectorXd(system.C) * V;
  system.A = D;
  return true;
}

ModePairStateSpace realize_kernel_entry(const RetardationKernel& kernel, int i, int j, int order, int max_hankel_size) {
  check_state_space_order(order);
  const int samples = static_cast<int>(kernel.values.size());
  const int stride = std::max(1, (samples - 1) / (2 * max_hankel_size - 1) + ((samples - 1) % (2 * max_hankel_size - 1) != 0));
  const double h = stride * kernel.time_step;
  std::vector<double> y;
  for (int k = 0; k < samples; k += stride) y.push_back(kernel.values[k](i, j));
  const int size = std::min<int>(max_hankel_size, (static_cast<int>(y.size()) - 1) / 2);
  // The Hankel matrix of 2 size + 1 samples has rank <= size: at least `order` rows.
  if (size < order)
    throw ParameterError("kernel_step",
                         fmt::format("a kernel of {} samples ({:g} s every {:g} s), which holds a Hankel matrix of "
                                     "size {} only",
                                     samples, kernel.duration(), kernel.time_step, size),
                         fmt::format("at least 2 x {} + 1 = {} samples for a state space of order {}: a shorter "
                                     "kernel_step, a longer kernel_duration or a lower state_space_order",
                                     order, 2 * order + 1, order));
  Eigen::MatrixXd H0(size, size), H1(size, size);
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      H0(r, c) = y[r + c];
      H1(r, c) = y[r + c + 1];
    }
  // The Hankel matrix is symmetric (H0(r, c) = y_{r+c}), so its SVD is its eigen-
  // decomposition H0 = Q diag(lambda) Q^T with sigma = |lambda|, U = Q and V = Q sign(lambda)
  // (Kung 1978 with a symmetric H0). A symmetric tridiagonal eigensolver is several times
  // faster than a general SVD of the 150 x 150 matrix of every mode pair, and its
  // instantiation compiles in a fraction of the time of Eigen's BDCSVD.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen_hankel(H0);
  const Eigen::VectorXd& lambda_hankel = eigen_hankel.eigenvalues();
  std::vector<Eigen::Index> by_magnitude(size);
  for (int k = 0; k < size; ++k) by_magnitude[k] = k;
  std::partial_sort(by_magnitude.begin(), by_magnitude.begin() + order, by_magnitude.end(),
                    [&](Eigen::Index a, Eigen::Index b) { return std::abs(lambda_hankel[a]) > std::abs(lambda_hankel[b]); });
  Eigen::VectorXd sigma(order);
  Eigen::MatrixXd U(size, order), V(size, order);
  for (int k = 0; k < order; ++k) {
    const double lambda = lambda_hankel[by_magnitude[k]];
    sigma[k] = std::abs(lambda);
    U.col(k) = eigen_hankel.eigenvectors().col(by_magnitude[k]);
    V.col(k) = lambda < 0.0 ? Eigen::VectorXd(-U.col(k)) : Eigen::VectorXd(U.col(k));
  }
  const Eigen::VectorXd root = sigma.cwiseSqrt(), inverse_root = root.cwiseInverse();
  // y_k = C A_d^k B with A_d = S^-1/2 U^T H1 V S^-1/2, B = S^1/2 V^T e_1, C = e_1^T U S^1/2.
  const Eigen::MatrixXd Ad = inverse_root.asDiagonal() * (U.transpose() * H1 * V) * inverse_root.asDiagonal();
  ModePairStateSpace system;
  system.force_mode = i;
  system.velocity_mode = j;
  system.B = root.asDiagonal() * V.row(0).transpose();
  system.C = U.row(0) * root.asDiagonal();
  Eigen::MatrixXd A = Ad.log().real() / h;
  // A realisation of a truncated kernel can carry a slightly unstable, lightly damped
  // pole; reflect such poles into the left half-plane (Re lambda -> -|Re lambda|),
  // which keeps their frequency and the fit of the decaying part.
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(A);
  Eigen::VectorXcd lambda = eigen.eigenvalues();
  if ((lambda.real().array() >= 0.0).any()) {
    for (Eigen::Index k = 0; k < lambda.size(); ++k)
      lambda[k] = std::complex<double>(-std::max(std::abs(lambda[k].real()), 1e-6), lambda[k].imag());
    const Eigen::MatrixXcd vectors = eigen.eigenvectors();
    A = (vectors * lambda.asDiagonal() * vectors.inverse()).real();
    system.reflected_poles = true;
  }
  system.A = A;
  system.stable = (Eigen::MatrixXd(system.A).eigenvalues().real().array() < 0.0).all();
  to_modal_form(system);
  // Fit quality on the full-rate samples.
  double mean = 0.0;
  for (const Matrix6& K : kernel.values) mean += K(i, j);
  mean /= samples;
  double residual = 0.0, total = 0.0;
  const Eigen::MatrixXd step = (Eigen::MatrixXd(system.A) * kernel.time_step).exp();
  Eigen::VectorXd x = system.B;
  for (int k = 0; k < samples; ++k) {
    const double fit = system.C * x;
    residual += std::pow(kernel.values[k](i, j) - fit, 2);
    total += std::pow(kernel.values[k](i, j) - mean, 2);
    x = step * x;
  }
  system.r_squared = total > 0.0 ? 1.0 - residual / total : 1.0;
  return system;
}

std::vector<ModePairStateSpace> realize_kernel(const RetardationKernel& kernel, int order, double threshold) {
  Matrix6 peak = Matrix6::Zero();
  for (const Matrix6& K : kernel.values) peak = peak.cwiseMax(K.cwiseAbs());
  const double largest = peak.diagonal().maxCoeff();
  std::vector<ModePairStateSpace> systems;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (peak(i, j) > threshold * largest) systems.push_back(realize_kernel_entry(kernel, i, j, order));
  return systems;
}

std::complex<double> frequency_response(const ModePairStateSpace& s, double w) {
  const int n = static_cast<int>(s.A.rows());
  const Eigen::MatrixXcd M = std::complex<double>(0.0, w) * Eigen::MatrixXcd::Identity(n, n) - Eigen::MatrixXd(s.A).cast<std::complex<double>>();
  const Eigen::VectorXcd x = M.partialPivLu().solve(Eigen::VectorXd(s.B).cast<std::complex<double>>());
  return (Eigen::RowVectorXd(s.C).cast<std::complex<double>>() * x)(0);
}

}  // namespace heavesim::hydro
