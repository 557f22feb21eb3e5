#pragma once
// One-pass central moments of a sampled signal up to the fourth, numerically stable:
// the update of Terriberry (2007) / Pébay (2008, Sandia report SAND2008-6212, eq. 2.1-2.4),
// which carries M2, M3, M4 (sums of powers of deviations from the running mean) so that no
// large sums of raw powers cancel. A block of samples is added by its own central sums
// (two passes over the block) merged with the totals by Pébay's pairwise formulas
// (SAND2008-6212, eq. 3.1): no division per sample, so the recorder's channels pay less
// for their moments (docs/performance.md).
#include <cstddef>
#include <cstdint>
#include <limits>

namespace heavesim::stats {

class MomentAccumulator {
 public:
  /// The central sums a block adds (add_rows): up to the fourth power (every moment), or
  /// up to the second, for an accumulator asked only for extremes, mean and standard
  /// deviation (it then reports NaN skewness and kurtosis, as does every merge into it).
  enum class Orders { up_to_fourth, up_to_second };
  void add(double x);
  /// The samples x[0], x[stride], ..., x[(count - 1) stride].
  void add(const double* x, std::ptrdiff_t stride, std::int64_t count);
  /// `count` rows of a row-major block with `width` values a row, column c into
  /// columns[c]: two passes over the block for all columns together (extremes and mean,
  /// then the central sums) instead of six strided passes per column.
  /// Orders::up_to_second leaves out the third and fourth powers of the second pass (the
  /// recorder's whole-record statistics before the evaluation window: docs/performance.md,
  /// "Issue #18, twenty-third round"); extremes, mean and M2 are the same, bit for bit.
  static void add_rows(MomentAccumulator* columns, std::ptrdiff_t width, const double* rows, std::int64_t count,
                       Orders orders = Orders::up_to_fourth);
  /// The samples of `other` as well (Pébay 2008, eq. 3.1): the moments of the two records
  /// together, to round-off those of adding all their samples to one accumulator.
  void merge(const MomentAccumulator& other) {
    if (other.count_ == 0) return;
    merge(other.count_, other.minimum_, other.maximum_, other.mean_, other.m2_, other.m3_, other.m4_);
    higher_orders_ = higher_orders_ && other.higher_orders_;
  }

  std::int64_t count() const { return count_; }
  double mean() const { return count_ > 0 ? mean_ : nan(); }
  double minimum() const { return count_ > 0 ? minimum_ : nan(); }
  double maximum() const { return count_ > 0 ? maximum_ : nan(); }
  /// Sample standard deviation, sqrt(M2 / (n - 1)) (units of the signal).
  double standard_deviation() const;
  /// Moment coefficient of skewness g1 = m3 / m2^(3/2) with m_k = M_k / n (the biased
  /// estimator; scipy.stats.skew(bias=True)); NaN for a constant signal.
  double skewness() const;
  /// Pearson's kurtosis m4 / m2^2 (3 for a Gaussian; scipy.stats.kurtosis(fisher=False,
  /// bias=True)); NaN for a constant signal.
  double kurtosis() const;
 private:
  /// Merges a block's count, extremes, mean and central sums M2, M3, M4 (about the block's
  /// own mean) into the totals (Pébay 2008, eq. 3.1).
  void merge(std::int64_t count, double minimum, double maximum, double mean, double m2, double m3, double m4);
  /// add_rows for the columns first .. first + n - 1 (n = Width, or runtime_n when Width
  /// is 0): see moment_accumulator.cpp. Not inlined into add_rows: with all seven widths
  /// inlined there, GCC 12's code for the drilling run took 4 % more instructions.
  template <int Width, Orders Up_to>
  [[gnu::noinline]] static void add_tile(MomentAccumulator* columns, std::ptrdiff_t width, const double* rows, std::int64_t count,
                       std::ptrdiff_t first, std::ptrdiff_t runtime_n);
  static double nan() { return std::numeric_limits<double>::quiet_NaN(); }
  std::int64_t count_ = 0;
  double mean_ = 0.0, m2_ = 0.0, m3_ = 0.0, m4_ = 0.0;
  double minimum_ = std::numeric_limits<double>::infinity();
  double maximum_ = -std::numeric_limits<double>::infinity();
  bool higher_orders_ = true;  // M3 and M4 hold every sample's powers (no second-order block)
};

}  // namespace heavesim::stats
