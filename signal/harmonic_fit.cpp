#include "signal/harmonic_fit.hpp"

#include <cmath>

#include <Eigen/QR>

namespace heavesim::stats {

std::complex<double> fit_harmonic(const double* times, const double* x, std::size_t n, double w) {
  Eigen::MatrixXd basis(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd values(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) {
    basis.row(static_cast<Eigen::Index>(k)) << std::cos(w * times[k]), std::sin(w * times[k]), 1.0;
    values[static_cast<Eigen::Index>(k)] = x[k];
  }
  const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(values);
  return {c[0], -c[1]};
}

}  // namespace heavesim::stats
