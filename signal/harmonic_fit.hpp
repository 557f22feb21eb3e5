#pragma once
// Steady response at one known frequency from a sampled record, by linear least squares:
//   x(t) ~ a cos(w t) + b sin(w t) + c  =>  x = c + Re[X e^{i w t}],  X = a - i b,
// the convention of the frequency-domain analysis (motion = Re[RAO a e^{i w t}],
// hydro/analysis/frequency_domain_rao.hpp). Over whole cycles of a steady record the
// three basis functions are orthogonal and X is the discrete Fourier coefficient; over
// any other span the least-squares solve keeps the mean out of X. Used by
// `heavesim rao` (regular-wave sweeps), validation H4 and the hydro response tests.
#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

namespace heavesim::stats {

/// The complex amplitude X [units of x] of the w [rad/s] component of the n samples
/// x[k] at times[k] [s] (n >= 3); colPivHouseholderQr of the n x 3 basis.
std::complex<double> fit_harmonic(const double* times, const double* x, std::size_t n, double angular_frequency);

inline std::complex<double> fit_harmonic(const std::vector<double>& times, const std::vector<double>& x,
                                         double angular_frequency) {
  return fit_harmonic(times.data(), x.data(), std::min(times.size(), x.size()), angular_frequency);
}

}  // namespace heavesim::stats
