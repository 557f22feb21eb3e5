#pragma once
// Per-column minimum, maximum, mean and standard deviation of a recorded channel,
// accumulated as the samples come: sample by sample (Welford's update) or a block of
// samples at a time (two passes over the block) (the block's own mean and sum of squared deviations, merged with the totals
// by Chan, Golub & LeVeque's pairwise formula, "Algorithms for computing the sample
// variance", The American Statistician 37, 1983).
#include <Eigen/Core>
#include <algorithm>
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

  /// One sample: a row of columns() values.
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
  /// `samples` samples stored row after row (columns() values a row): per column, the
  /// block's mean m_b and sum of squared deviations S_b in two passes, then
  ///   n = n_a + n_b, d = m_b - m_a, mean = m_a + d n_b / n, S = S_a + S_b + d^2 n_a n_b / n.
  void add_rows(const double* rows, long samples) {
    if (samples <= 0) return;
    const Eigen::Index width = static_cast<Eigen::Index>(mean_.size());
    if (width == 1) {  // a scalar series: contiguous, so Eigen's reductions vectorize
      add_column(0, Eigen::Map<const Eigen::ArrayXd>(rows, samples), samples);
    } else {
      using Block = Eigen::Map<const Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;
      const Block block(rows, samples, width);
      for (Eigen::Index c = 0; c < width; ++c) add_column(c, block.col(c), samples);
    }
    count_ += samples;
  }
  long count() const { return count_; }
  int columns() const { return static_cast<int>(mean_.size()); }
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
  template <class Column>
  void add_column(Eigen::Index c, const Column& column, long samples) {
    const double n_a = static_cast<double>(count_), n_b = static_cast<double>(samples), n = n_a + n_b;
    minimum_[c] = std::min(minimum_[c], column.minCoeff());
    maximum_[c] = std::max(maximum_[c], column.maxCoeff());
    const double block_mean = column.sum() / n_b;
    const double block_squares = (column - block_mean).square().sum();
    const double delta = block_mean - mean_[c];
    mean_[c] += delta * (n_b / n);
    sum_squares_[c] += block_squares + delta * delta * (n_a * n_b / n);
  }

  long count_ = 0;
  std::vector<double> minimum_, maximum_, mean_, sum_squares_;
};

}  // namespace heavesim
