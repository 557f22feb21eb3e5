#include "signal/moment_accumulator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "signal/fixed_width.hpp"

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

namespace {

/// A block's count, extremes, mean and central sums M2, M3, M4 (the mean first, then the
/// deviations from it): Eigen reductions, vectorized over a contiguous block.
struct BlockSums {
  double count, minimum, maximum, mean, m2, m3, m4;
};
template <class Values>
BlockSums block_sums(const Values& values) {
  const double count = static_cast<double>(values.size()), mean = values.sum() / count;
  const auto deviation = values - mean;
  return {count,
          values.minCoeff(),
          values.maxCoeff(),
          mean,
          deviation.square().sum(),
          (deviation.square() * deviation).sum(),
          deviation.square().square().sum()};
}

}  // namespace

void MomentAccumulator::add(const double* x, std::ptrdiff_t stride, std::int64_t count) {
  if (count <= 0) return;
  const BlockSums block =
      stride == 1 ? block_sums(Eigen::Map<const Eigen::ArrayXd>(x, count))
                  : block_sums(Eigen::Map<const Eigen::ArrayXd, 0, Eigen::InnerStride<>>(x, count, Eigen::InnerStride<>(stride)));
  merge(count, block.minimum, block.maximum, block.mean, block.m2, block.m3, block.m4);
}

/// Columns first .. first + n - 1 of `count` rows (`width` values a row) into
/// columns[first ..]: their extremes and mean, then their central sums, in registers.
/// `Width` > 0 fixes n at compile time: the inner loops unroll and pair columns in SIMD
/// registers instead of looping over 1 to 8 columns per row (the recorder's series are 1,
/// 3 or 6 columns wide; the drilling run's whole-record moments took 28 instructions a
/// value, docs/performance.md, "Issue #18, eleventh round"). Each column still adds its rows
/// in order, so the sums are the same, bit for bit, whichever path adds them.
template <int Width, MomentAccumulator::Orders Up_to>
void MomentAccumulator::add_tile(MomentAccumulator* columns, std::ptrdiff_t width, const double* rows,
                                 std::int64_t count, std::ptrdiff_t first, std::ptrdiff_t runtime_n) {
  constexpr bool fourth = Up_to == Orders::up_to_fourth;
  constexpr std::ptrdiff_t tile = 8;
  const std::ptrdiff_t n = Width > 0 ? Width : runtime_n;
  double sum[tile] = {}, minimum[tile], maximum[tile], mean[tile], m2[tile] = {}, m3[tile] = {}, m4[tile] = {};
  std::fill_n(minimum, tile, std::numeric_limits<double>::infinity());
  std::fill_n(maximum, tile, -std::numeric_limits<double>::infinity());
  for (std::int64_t r = 0; r < count; ++r) {
    const double* row = rows + r * width + first;
    for (std::ptrdiff_t c = 0; c < n; ++c) {
      sum[c] += row[c];
      minimum[c] = std::min(minimum[c], row[c]);
      maximum[c] = std::max(maximum[c], row[c]);
    }
  }
  for (std::ptrdiff_t c = 0; c < n; ++c) mean[c] = sum[c] / static_cast<double>(count);
  // The central sums from the block's own mean: no large powers cancel (as add(x, stride, n)).
  for (std::int64_t r = 0; r < count; ++r) {
    const double* row = rows + r * width + first;
    for (std::ptrdiff_t c = 0; c < n; ++c) {
      const double deviation = row[c] - mean[c], square = deviation * deviation;
      m2[c] += square;
      if constexpr (fourth) {
        m3[c] += square * deviation;
        m4[c] += square * square;
      }
    }
  }
  for (std::ptrdiff_t c = 0; c < n; ++c) {
    columns[first + c].merge(count, minimum[c], maximum[c], mean[c], m2[c], m3[c], m4[c]);
    if constexpr (!fourth) columns[first + c].higher_orders_ = false;
  }
}

void MomentAccumulator::add_rows(MomentAccumulator* columns, std::ptrdiff_t width, const double* rows,
                                 std::int64_t count, Orders orders) {
  if (count <= 0) return;
  // Columns a tile of at most 8 at a time, so that the tile's sums stay in registers.
  constexpr std::ptrdiff_t tile = 8;
  for (std::ptrdiff_t first = 0; first < width; first += tile) {
    const std::ptrdiff_t n = std::min(tile, width - first);
    call_with_fixed_width<1, 2, 3, 4, 6, 8>(n, [&](auto fixed) {
      constexpr int fixed_width = decltype(fixed)::value;
      if (orders == Orders::up_to_second)
        add_tile<fixed_width, Orders::up_to_second>(columns, width, rows, count, first, n);
      else
        add_tile<fixed_width, Orders::up_to_fourth>(columns, width, rows, count, first, n);
    });
  }
}

void MomentAccumulator::merge(std::int64_t count, double minimum, double maximum, double mean_b, double m2_b,
                              double m3_b, double m4_b) {
  minimum_ = std::min(minimum_, minimum);
  maximum_ = std::max(maximum_, maximum);
  if (count_ == 0) {
    count_ = count;
    mean_ = mean_b;
    m2_ = m2_b;
    m3_ = m3_b;
    m4_ = m4_b;
    return;
  }
  // Pébay (2008) eq. 3.1 with A the samples so far, B the block, delta = mean_B - mean_A.
  const double n_a = static_cast<double>(count_), n_b = static_cast<double>(count), n = n_a + n_b;
  const double delta = mean_b - mean_, delta_n = delta / n;
  const double product = n_a * n_b;
  m4_ += m4_b + delta * delta_n * delta_n * delta_n * product * (n_a * n_a - product + n_b * n_b) +
         6.0 * delta_n * delta_n * (n_a * n_a * m2_b + n_b * n_b * m2_) + 4.0 * delta_n * (n_a * m3_b - n_b * m3_);
  m3_ += m3_b + delta * delta_n * delta_n * product * (n_a - n_b) + 3.0 * delta_n * (n_a * m2_b - n_b * m2_);
  m2_ += m2_b + delta * delta_n * product;
  mean_ += delta_n * n_b;
  count_ += count;
}

double MomentAccumulator::standard_deviation() const {
  if (count_ < 2) return nan();
  return std::sqrt(m2_ / static_cast<double>(count_ - 1));
}

double MomentAccumulator::skewness() const {
  if (count_ < 2 || !(m2_ > 0.0) || !higher_orders_) return nan();
  const double n = static_cast<double>(count_);
  return std::sqrt(n) * m3_ / std::pow(m2_, 1.5);
}

double MomentAccumulator::kurtosis() const {
  if (count_ < 2 || !(m2_ > 0.0) || !higher_orders_) return nan();
  return static_cast<double>(count_) * m4_ / (m2_ * m2_);
}

}  // namespace heavesim::stats
