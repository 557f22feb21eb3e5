#include "signal/welch_spectrum.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace heavesim::stats {

double SpectralMoments::zero_upcrossing_period() const {
  if (!(m0 > 0.0 && m2 > 0.0)) return std::numeric_limits<double>::quiet_NaN();  // no variance: no period
  return std::sqrt(m0 / m2);
}

double SpectralMoments::bandwidth() const {
  if (!(m0 > 0.0 && m4 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double ratio = m2 * m2 / (m0 * m4);
  return std::sqrt(std::max(0.0, 1.0 - ratio));
}

WelchAccumulator::WelchAccumulator(int segment_length, double sampling_frequency)
    : sampling_frequency_(sampling_frequency) {
  if (segment_length < 4 || segment_length % 2 != 0)
    throw std::invalid_argument(fmt::format("Welch segment length {}: expected an even number >= 4", segment_length));
  if (!(sampling_frequency > 0.0) || !std::isfinite(sampling_frequency))
    throw std::invalid_argument(fmt::format("sampling frequency {} Hz: expected > 0", sampling_frequency));
  const int L = segment_length;
  window_.resize(L);
  for (int n = 0; n < L; ++n) {
    window_[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
    window_power_ += window_[n] * window_[n];
  }
  buffer_.resize(L);
  segment_.resize(L);
  power_sum_.assign(L / 2 + 1, 0.0);
  transform_.resize(L);
}

void WelchAccumulator::add(double x) {
  buffer_[filled_++] = x;
  if (filled_ < static_cast<int>(buffer_.size())) return;
  add_segment();
  const int half = static_cast<int>(buffer_.size()) / 2;
  std::copy(buffer_.begin() + half, buffer_.end(), buffer_.begin());
  filled_ = half;
}

void WelchAccumulator::add_segment() {
  const std::size_t L = buffer_.size();
  double mean = 0.0;
  for (double v : buffer_) mean += v;
  mean /= static_cast<double>(L);
  for (std::size_t n = 0; n < L; ++n) segment_[n] = (buffer_[n] - mean) * window_[n];
  // One transform object a thread: its plans (twiddle factors per length) are made once,
  // not once per channel column.
  thread_local Eigen::FFT<double> fft = [] {
    Eigen::FFT<double> made;
    made.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real input: bins 0 .. L/2 only
    return made;
  }();
  fft.fwd(transform_, segment_);
  for (std::size_t k = 0; k < power_sum_.size(); ++k) power_sum_[k] += std::norm(transform_[k]);
  ++segments_;
}

std::vector<double> WelchAccumulator::frequencies() const {
  std::vector<double> f(power_sum_.size());
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = sampling_frequency_ * static_cast<double>(k) / window_.size();
  return f;
}

std::vector<double> WelchAccumulator::density() const {
  if (segments_ == 0) return {};
  std::vector<double> s(power_sum_.size());
  const double scale = 1.0 / (sampling_frequency_ * window_power_ * static_cast<double>(segments_));
  for (std::size_t k = 0; k < s.size(); ++k) {
    const bool edge = k == 0 || k + 1 == s.size();  // DC and Nyquist have no mirror bin
    s[k] = (edge ? 1.0 : 2.0) * power_sum_[k] * scale;
  }
  return s;
}

SpectralMoments WelchAccumulator::moments() const { return spectral_moments(frequencies(), density()); }

SpectralMoments spectral_moments(const std::vector<double>& f, const std::vector<double>& s) {
  SpectralMoments moments;
  if (s.size() < 2 || f.size() != s.size()) return moments;
  const double df = f[1] - f[0];
  double m0 = 0.0, m2 = 0.0, m4 = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double f2 = f[k] * f[k];
    m0 += s[k] * df;
    m2 += f2 * s[k] * df;
    m4 += f2 * f2 * s[k] * df;
    if (k > 0 && s[k] > largest) {
      largest = s[k];
      moments.peak_period = 1.0 / f[k];
    }
  }
  moments.m0 = m0;
  moments.m2 = m2;
  moments.m4 = m4;
  return moments;
}

}  // namespace heavesim::stats
