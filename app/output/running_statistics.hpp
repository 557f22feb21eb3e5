#pragma once
// Per-column minimum, maximum, mean and standard deviation of a recorded channel,
// accumulated as the samples come, sample by sample or a block of samples at a time: one
// stats::MomentAccumulator per column (signal/moment_accumulator.hpp: Welford's update,
// and for a block its own sums merged with the totals by the pairwise formulas of Chan,
// Golub & LeVeque 1983 and Pébay 2008).
#include <cmath>
#include <limits>
#include <vector>

#include "signal/moment_accumulator.hpp"

namespace heavesim {

class RunningStatistics {
 public:
  RunningStatistics() : RunningStatistics(1) {}
  explicit RunningStatistics(int columns) : columns_(columns) {}

  /// One sample: a row of one value per column.
  void add(const double* row) {
    for (std::size_t c = 0; c < columns_.size(); ++c) columns_[c].add(row[c]);
  }
  /// `samples` samples stored row after row (one value per column a row). Their central
  /// sums up to the second power only: these statistics report no higher moment.
  void add_rows(const double* rows, long samples) {
    stats::MomentAccumulator::add_rows(columns_.data(), static_cast<std::ptrdiff_t>(columns_.size()), rows, samples,
                                       stats::MomentAccumulator::Orders::up_to_second);
  }
  /// Column `column` takes the samples `other` accumulated as well.
  void merge(int column, const stats::MomentAccumulator& other) { columns_.at(column).merge(other); }
  long count() const { return static_cast<long>(columns_[0].count()); }
  /// +inf before the first sample.
  std::vector<double> minimum() const {
    return each([](const stats::MomentAccumulator& m) {
      return m.count() > 0 ? m.minimum() : std::numeric_limits<double>::infinity();
    });
  }
  /// -inf before the first sample.
  std::vector<double> maximum() const {
    return each([](const stats::MomentAccumulator& m) {
      return m.count() > 0 ? m.maximum() : -std::numeric_limits<double>::infinity();
    });
  }
  /// 0 before the first sample.
  std::vector<double> mean() const {
    return each([](const stats::MomentAccumulator& m) { return m.count() > 0 ? m.mean() : 0.0; });
  }
  /// Sample standard deviation; 0 for fewer than two samples.
  std::vector<double> standard_deviation() const {
    return each([](const stats::MomentAccumulator& m) { return m.count() > 1 ? m.standard_deviation() : 0.0; });
  }

 private:
  template <class Field>
  std::vector<double> each(Field field) const {
    std::vector<double> values;
    values.reserve(columns_.size());
    for (const stats::MomentAccumulator& column : columns_) values.push_back(field(column));
    return values;
  }
  std::vector<stats::MomentAccumulator> columns_;
};

}  // namespace heavesim
