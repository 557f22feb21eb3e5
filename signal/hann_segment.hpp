#pragma once
// One segment of Welch's method (Welch 1967, IEEE Trans. Audio Electroacoust. 15(2)):
// L samples, their mean removed, times the periodic Hann window
// w_n = (1 - cos(2 pi n / L)) / 2, and their discrete Fourier transform
// X_k = sum_n x_n w_n e^(-2 pi i k n / L) for k = 0 .. L/2 (FFTW's real-to-complex
// transform, Frigo & Johnson 2005, Proc. IEEE 93(2)). Shared by the power spectrum
// (welch_spectrum.hpp) and the cross spectrum (cross_spectrum.hpp), so that both see the
// same window and scaling.
#include <complex>
#include <vector>

namespace heavesim::stats {

/// What every transform of one length shares (signal/hann_segment.cpp): the window and
/// FFTW's plan, made once per length and kept for the life of the process.
struct HannSegmentLength;

class HannSegmentTransform {
 public:
  /// `segment_length` L: even, >= 4 (std::invalid_argument otherwise).
  explicit HannSegmentTransform(int segment_length);
  int length() const;
  /// sum w_n^2: the window's power, the density's normalisation S = c |X|^2 / (fs sum w^2).
  double window_power() const;
  /// X_k, k = 0 .. L/2, of the L samples from `samples` (valid until the next call).
  const std::vector<std::complex<double>>& transform(const double* samples);
  /// power_sums[k] += |X_k|^2, k = 0 .. L/2, for the L samples from `samples`: the
  /// transform stays in the calling thread's scratch, so a caller that keeps only the
  /// periodogram's sums (Welch) holds no bins of its own (a recorder has one per column).
  void add_power(const double* samples, double* power_sums);

 private:
  /// Shared with every transform of the same length: a recorder holds one transform per
  /// recorded column (hundreds), each of which would otherwise take L cosines, L doubles
  /// and a plan.
  HannSegmentLength* shared_ = nullptr;
  std::vector<std::complex<double>> transform_;  // L/2 + 1 bins, sized by the first transform()
};

}  // namespace heavesim::stats
