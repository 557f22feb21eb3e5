#pragma once
// Steady response at one frequency from a sampled record, by linear least squares:
//   x(t) ~ a cos(w t) + b sin(w t) + c  =>  x = Re[X e^{i w t}] + c,  X = a - i b.
// Used where a record is compared with a frequency-domain response after its ramp
// (validation H4, the hydro response tests).
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/QR>

namespace heavesim::validation {

/// The complex amplitude X [units of x] of the w [rad/s] component of x(times).
inline std::complex<double> fit_harmonic(const std::vector<double>& times, const std::vector<double>& x, double w) {
  Eigen::MatrixXd basis(times.size(), 3);
  Eigen::VectorXd values(times.size());
  for (std::size_t n = 0; n < times.size(); ++n) {
    basis.row(n) << std::cos(w * times[n]), std::sin(w * times[n]), 1.0;
    values[n] = x[n];
  }
  const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(values);
  return {c[0], -c[1]};
}

}  // namespace heavesim::validation
