#pragma once
// One-sided power spectral density by Welch's method (Welch 1967, IEEE Trans. Audio
// Electroacoust. 15(2)): the signal cut into segments of L samples overlapping by L/2,
// each segment's mean removed and multiplied by a periodic Hann window
// w_n = (1 - cos(2 pi n / L)) / 2, its discrete Fourier transform X_k taken (FFTW, real input),
// and the periodograms averaged:
//   S(f_k) = c_k |X_k|^2 / (fs sum w_n^2),  f_k = k fs / L,  c_k = 2 except c_0 = c_(L/2) = 1,
// in units^2/Hz, so that sum S(f_k) df equals the variance (Parseval). These are the
// defaults of scipy.signal.welch (window 'hann', noverlap L/2, detrend 'constant',
// scaling 'density'), which the tests compare with.
//
// Streaming: a buffer of L samples; each time it fills, the segment's periodogram is
// added and the buffer keeps its second half. Memory L + L/2 + 1 numbers, whatever the
// record's length, taken at the first sample.
#include <cstdint>
#include <limits>
#include <vector>

#include "signal/hann_segment.hpp"

namespace heavesim::stats {

/// Moments of a one-sided density S(f) in Hz: m_n = sum f^n S(f) df (units^2 Hz^n).
struct SpectralMoments {
  double m0 = std::numeric_limits<double>::quiet_NaN();  // units^2 (the variance)
  double m2 = std::numeric_limits<double>::quiet_NaN();  // units^2 Hz^2
  double m4 = std::numeric_limits<double>::quiet_NaN();  // units^2 Hz^4
  double peak_period = std::numeric_limits<double>::quiet_NaN();  // Tp = 1 / f at the largest S, s
  /// Rice's zero up-crossing period sqrt(m0 / m2) (Hz moments; 2 pi sqrt(m0/m2) in rad/s), s.
  double zero_upcrossing_period() const;
  /// Spectral bandwidth epsilon = sqrt(1 - m2^2 / (m0 m4)) (Cartwright & Longuet-Higgins 1956), -.
  double bandwidth() const;
};

class WelchAccumulator {
 public:
  /// `segment_length` L: even, >= 4; `sampling_frequency` fs in Hz.
  WelchAccumulator(int segment_length, double sampling_frequency);
  void add(double x);
  /// The samples x[0..count), in time order (as many add(x) calls, copied a run at a time).
  void add(const double* x, std::int64_t count);
  std::int64_t segments() const { return segments_; }
  int segment_length() const { return segment_transform_.length(); }
  /// f_k = k fs / L, k = 0 .. L/2 (Hz).
  std::vector<double> frequencies() const;
  /// S(f_k) (units^2/Hz); empty before the first whole segment.
  std::vector<double> density() const;
  SpectralMoments moments() const;

 private:
  /// The full buffer's periodogram into the sums; its second half begins the next segment.
  void add_segment();
  /// Sizes the buffer (L) and the sums (L/2 + 1, zero): at the first sample.
  void allocate();
  double sampling_frequency_;
  HannSegmentTransform segment_transform_;
  std::vector<double> buffer_, power_sum_;
  int filled_ = 0;
  std::int64_t segments_ = 0;
};

/// The moments, Tp included, of a density sampled at uniformly spaced frequencies.
SpectralMoments spectral_moments(const std::vector<double>& frequencies, const std::vector<double>& density);

}  // namespace heavesim::stats
