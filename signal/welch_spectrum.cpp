#include "signal/welch_spectrum.hpp"

#include <algorithm>
#include <cmath>
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
    : sampling_frequency_(sampling_frequency), segment_transform_(segment_length) {
  if (!(sampling_frequency > 0.0) || !std::isfinite(sampling_frequency))
    throw std::invalid_argument(fmt::format("sampling frequency {} Hz: expected > 0", sampling_frequency));
}

// The buffer and the sums are made by the first sample, not by the constructor: a recorder
// makes one accumulator per column before the run, on the thread that then integrates, and
// its samples arrive later on the thread that computes the statistics, which then also
// pays for the memory's first touch (docs/performance.md, "Issue #18, eighteenth round").
void WelchAccumulator::allocate() {
  const int L = segment_transform_.length();
  power_sum_.assign(L / 2 + 1, 0.0);
  buffer_.resize(L);  // last: an empty buffer is what add() takes for "not made yet"
}

void WelchAccumulator::add(double x) {
  if (buffer_.empty()) allocate();
  buffer_[filled_++] = x;
  if (filled_ == static_cast<int>(buffer_.size())) add_segment();
}

void WelchAccumulator::add(const double* x, std::int64_t count) {
  if (count > 0 && buffer_.empty()) allocate();
  while (count > 0) {
    const std::int64_t taken = std::min(count, static_cast<std::int64_t>(buffer_.size()) - filled_);
    std::copy_n(x, taken, buffer_.begin() + filled_);
    filled_ += static_cast<int>(taken);
    x += taken;
    count -= taken;
    if (filled_ == static_cast<int>(buffer_.size())) add_segment();
  }
}

void WelchAccumulator::add_segment() {
  segment_transform_.add_power(buffer_.data(), power_sum_.data());
  ++segments_;
  // 50 % overlap: the segment's second half begins the next one.
  const int half = static_cast<int>(buffer_.size()) / 2;
  std::copy(buffer_.begin() + half, buffer_.end(), buffer_.begin());
  filled_ = half;
}

std::vector<double> WelchAccumulator::frequencies() const {
  const int L = segment_transform_.length();
  std::vector<double> f(L / 2 + 1);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = sampling_frequency_ * static_cast<double>(k) / L;
  return f;
}

std::vector<double> WelchAccumulator::density() const {
  if (segments_ == 0) return {};
  std::vector<double> s(power_sum_.size());
  const double scale = 1.0 / (sampling_frequency_ * segment_transform_.window_power() * static_cast<double>(segments_));
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
