#include "signal/hann_segment.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

namespace heavesim::stats {

HannSegmentTransform::HannSegmentTransform(int segment_length) {
  if (segment_length < 4 || segment_length % 2 != 0)
    throw std::invalid_argument(fmt::format("Welch segment length {}: expected an even number >= 4", segment_length));
  const int L = segment_length;
  window_.resize(L);
  for (int n = 0; n < L; ++n) {
    window_[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
    window_power_ += window_[n] * window_[n];
  }
  segment_.resize(L);
  transform_.resize(L);
}

const std::vector<std::complex<double>>& HannSegmentTransform::transform(const double* samples) {
  const std::size_t L = window_.size();
  double mean = 0.0;
  for (std::size_t n = 0; n < L; ++n) mean += samples[n];
  mean /= static_cast<double>(L);
  for (std::size_t n = 0; n < L; ++n) segment_[n] = (samples[n] - mean) * window_[n];
  // One transform object a thread: its plans (twiddle factors per length) are made once,
  // not once per channel column.
  thread_local Eigen::FFT<double> fft = [] {
    Eigen::FFT<double> made;
    made.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real input: bins 0 .. L/2 only
    return made;
  }();
  fft.fwd(transform_, segment_);
  return transform_;
}

}  // namespace heavesim::stats
