#pragma once
// One segment of Welch's method (Welch 1967, IEEE Trans. Audio Electroacoust. 15(2)):
// L samples, their mean removed, times the periodic Hann window
// w_n = (1 - cos(2 pi n / L)) / 2, and their discrete Fourier transform
// X_k = sum_n x_n w_n e^(-2 pi i k n / L) for k = 0 .. L/2 (Eigen's FFT, half spectrum of
// a real input). Shared by the power spectrum (welch_spectrum.hpp) and the cross spectrum
// (cross_spectrum.hpp), so that both see the same window and scaling.
#include <complex>
#include <vector>

namespace heavesim::stats {

class HannSegmentTransform {
 public:
  /// `segment_length` L: even, >= 4 (std::invalid_argument otherwise).
  explicit HannSegmentTransform(int segment_length);
  int length() const { return static_cast<int>(window_.size()); }
  /// sum w_n^2: the window's power, the density's normalisation S = c |X|^2 / (fs sum w^2).
  double window_power() const { return window_power_; }
  /// X_k, k = 0 .. L/2, of the L samples from `samples` (valid until the next call).
  const std::vector<std::complex<double>>& transform(const double* samples);

 private:
  std::vector<double> window_, segment_;
  std::vector<std::complex<double>> transform_;
  double window_power_ = 0.0;
};

}  // namespace heavesim::stats
