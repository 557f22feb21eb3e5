#include "signal/hann_segment.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

namespace heavesim::stats {

std::shared_ptr<const HannSegmentTransform::Window> HannSegmentTransform::window_of_length(int segment_length) {
  // Transforms are made on several threads (a sweep's runs); the windows they share are
  // immutable once made. An entry whose last transform has gone is made again.
  static std::mutex mutex;
  static std::map<int, std::weak_ptr<const Window>> windows;
  const std::lock_guard lock(mutex);
  std::weak_ptr<const Window>& entry = windows[segment_length];
  if (std::shared_ptr<const Window> existing = entry.lock()) return existing;
  auto window = std::make_shared<Window>();
  const int L = segment_length;
  window->coefficients.resize(L);
  for (int n = 0; n < L; ++n) {
    window->coefficients[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
    window->power += window->coefficients[n] * window->coefficients[n];
  }
  entry = window;
  return window;
}

HannSegmentTransform::HannSegmentTransform(int segment_length) {
  if (segment_length < 4 || segment_length % 2 != 0)
    throw std::invalid_argument(fmt::format("Welch segment length {}: expected an even number >= 4", segment_length));
  window_ = window_of_length(segment_length);
}

const std::vector<std::complex<double>>& HannSegmentTransform::transform(const double* samples) {
  const std::vector<double>& window = window_->coefficients;
  const std::size_t L = window.size();
  double mean = 0.0;
  for (std::size_t n = 0; n < L; ++n) mean += samples[n];
  mean /= static_cast<double>(L);
  // The windowed segment is scratch of this call only: one buffer a thread, not one a transform.
  thread_local std::vector<double> segment;
  segment.resize(L);
  for (std::size_t n = 0; n < L; ++n) segment[n] = (samples[n] - mean) * window[n];
  // One transform object a thread: its plans (twiddle factors per length) are made once,
  // not once per channel column.
  thread_local Eigen::FFT<double> fft = [] {
    Eigen::FFT<double> made;
    made.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real input: bins 0 .. L/2 only
    return made;
  }();
  fft.fwd(transform_, segment);
  return transform_;
}

}  // namespace heavesim::stats
