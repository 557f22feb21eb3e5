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

/// Mean period [s] of an oscillating record from its zero crossings (linearly
/// interpolated between samples): twice the mean spacing of the crossings; 0 with fewer
/// than three crossings. Used for free-decay periods (hydro cases).
inline double crossing_period(const std::vector<double>& times, const std::vector<double>& x) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < x.size(); ++k)
    if ((x[k - 1] > 0) != (x[k] > 0)) crossings.push_back(times[k - 1] - x[k - 1] * (times[k] - times[k - 1]) / (x[k] - x[k - 1]));
  if (crossings.size() < 3) return 0.0;
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace heavesim::validation
