#include "signal/moment_accumulator.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim::stats {

void MomentAccumulator::add(double x) {
  minimum_ = std::min(minimum_, x);
  maximum_ = std::max(maximum_, x);
  const double n_before = static_cast<double>(count_);
  ++count_;
  const double n = static_cast<double>(count_);
  const double delta = x - mean_;
  const double delta_n = delta / n;
  const double delta_n2 = delta_n * delta_n;
  const double term = delta * delta_n * n_before;
  mean_ += delta_n;
  // Pébay (2008) eq. (2.4), (2.3), (2.2): M4 and M3 use the previous M2 and M3.
  m4_ += term * delta_n2 * (n * n - 3.0 * n + 3.0) + 6.0 * delta_n2 * m2_ - 4.0 * delta_n * m3_;
  m3_ += term * delta_n * (n - 2.0) - 3.0 * delta_n * m2_;
  m2_ += term;
}

double MomentAccumulator::standard_deviation() const {
  if (count_ < 2) return nan();
  return std::sqrt(m2_ / static_cast<double>(count_ - 1));
}

double MomentAccumulator::skewness() const {
  if (count_ < 2 || !(m2_ > 0.0)) return nan();
  const double n = static_cast<double>(count_);
  return std::sqrt(n) * m3_ / std::pow(m2_, 1.5);
}

double MomentAccumulator::kurtosis() const {
  if (count_ < 2 || !(m2_ > 0.0)) return nan();
  return static_cast<double>(count_) * m4_ / (m2_ * m2_);
}

}  // namespace heavesim::stats
