#pragma once
// Frequency response of a system from records of its input x and output y (a wave
// elevation and a motion, a load, a stroke): Welch-averaged one-sided spectral densities
//   G_xx(f_k) = c_k <|X_k|^2> / (fs sum w^2),  G_yy likewise,
//   G_xy(f_k) = c_k <conj(X_k) Y_k> / (fs sum w^2)            (scipy.signal.csd's convention),
// over half-overlapping Hann segments (hann_segment.hpp), and from them
//   H1(f) = G_xy / G_xx           the estimator unbiased by noise on the output
//                                 (Bendat & Piersol 2010, Random Data, 4th ed., §9.1.4),
//   gamma^2(f) = |G_xy|^2 / (G_xx G_yy)   the ordinary coherence, 1 for a noise-free linear
//                                 system, lower where the output holds what the input does
//                                 not explain (transients, nonlinearity, leakage).
// With x = Re[a e^(i w t)] and y = Re[xi a e^(i w t)], H1 = xi: the RAO in the
// convention motion = Re[RAO a e^(i w t)] of the frequency-domain analysis.
// The random error of |H1| is about sqrt(1 - gamma^2) / (|gamma| sqrt(2 n_d)) for n_d
// segments (Bendat & Piersol, Table 9.6).
#include <complex>
#include <vector>

namespace heavesim::stats {

struct CrossSpectralEstimate {
  std::vector<double> frequencies;                  // f_k = k fs / L, k = 0 .. L/2, Hz
  std::vector<double> input_density;                // G_xx, input units^2 / Hz
  std::vector<double> output_density;               // G_yy, output units^2 / Hz
  std::vector<std::complex<double>> cross_density;  // G_xy, input units * output units / Hz
  int segments = 0;                                 // n_d, half-overlapping

  /// H1(f_k) = G_xy / G_xx (output units per input unit); NaN where G_xx = 0.
  std::complex<double> transfer_function(std::size_t k) const;
  /// gamma^2(f_k) in [0, 1]; NaN where either density is 0.
  double coherence(std::size_t k) const;
};

/// The estimate from two records of equal length sampled at `sampling_frequency` (Hz),
/// in segments of `segment_length` samples (even, >= 4, at most the records' length);
/// std::invalid_argument otherwise.
CrossSpectralEstimate cross_spectral_density(const std::vector<double>& input, const std::vector<double>& output,
                                             int segment_length, double sampling_frequency);

}  // namespace heavesim::stats
