#pragma once
// Per-column minimum, maximum, mean and standard deviation of a recorded channel,
// accumulated in one pass (Welford's algorithm).
#include <cmath>
#include <limits>
#include <vector>

namespace heavesim {

class RunningStatistics {
 public:
  RunningStatistics() : RunningStatistics(1) {}
  explicit RunningStatistics(int columns)
      : minimum_(columns, std::numeric_limits<double>::infinity()),
        maximum_(columns, -std::numeric_limits<double>::infinity()),
        mean_(columns, 0.0),
        sum_squares_(columns, 0.0) {}

  void add(const double* row) {
    ++count_;
    for (std::size_t c = 0; c < mean_.size(); ++c) {
      minimum_[c] = std::min(minimum_[c], row[c]);
      maximum_[c] = std::max(maximum_[c], row[c]);
      const double delta = row[c] - mean_[c];
      mean_[c] += delta / static_cast<double>(count_);
      sum_squares_[c] += delta * (row[c] - mean_[c]);
    }
  }
  long count() const { return count_; }
  const std::vector<double>& minimum() const { return minimum_; }
  const std::vector<double>& maximum() const { return maximum_; }
  const std::vector<double>& mean() const { return mean_; }
  std::vector<double> standard_deviation() const {
    std::vector<double> result(mean_.size(), 0.0);
    if (count_ > 1)
      for (std::size_t c = 0; c < result.size(); ++c) result[c] = std::sqrt(sum_squares_[c] / (count_ - 1));
    return result;
  }

 private:
  long count_ = 0;
  std::vector<double> minimum_, maximum_, mean_, sum_squares_;
};

}  // namespace heavesim
