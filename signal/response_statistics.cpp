#include "signal/response_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace heavesim::stats {

int default_segment_length(std::int64_t samples) {
  int length = 4;
  while (length * 2 <= 4096 && static_cast<std::int64_t>(length) * 2 * 4 <= samples) length *= 2;
  return static_cast<std::int64_t>(length) * 4 <= samples ? length : 0;
}

ResponseStatisticsAccumulator::ResponseStatisticsAccumulator(const StatisticsOptions& options,
                                                             std::int64_t record_samples)
    : options_(options) {
  if (!(options.time_step > 0.0) || !std::isfinite(options.time_step))
    throw std::invalid_argument(fmt::format("time step {} s: expected > 0", options.time_step));
  const int length = options.segment_length == 0 ? default_segment_length(record_samples) : options.segment_length;
  if (length > 0) welch_.emplace(length, 1.0 / options.time_step);
}

void ResponseStatisticsAccumulator::add(double x) {
  moments_.add(x);
  if (options_.cycles) turning_points_.add(x);
  if (welch_) welch_->add(x);
}

void ResponseStatisticsAccumulator::add(const double* x, std::ptrdiff_t stride, std::int64_t count) {
  if (stride != 1) {
    // A column of a row-major block: copied once, a bounded run at a time, so that the
    // moments' reductions vectorise and the Welch segments fill a run at a time (the
    // recorder's block statistics, docs/performance.md).
    constexpr std::int64_t run = 4096;
    thread_local std::vector<double> column;
    for (std::int64_t first = 0; first < count; first += run) {
      const std::int64_t taken = std::min(run, count - first);
      column.resize(static_cast<std::size_t>(taken));
      for (std::int64_t k = 0; k < taken; ++k) column[k] = x[(first + k) * stride];
      add(column.data(), 1, taken);
    }
    return;
  }
  moments_.add(x, 1, count);
  if (options_.cycles)
    for (std::int64_t k = 0; k < count; ++k) turning_points_.add(x[k]);
  if (welch_) welch_->add(x, count);
}

double mean_of_extreme_third(std::vector<double> values, bool largest) {
  const std::size_t third = values.size() / 3;
  if (third == 0) return ResponseStatistics::nan;
  if (largest)
    std::nth_element(values.begin(), values.begin() + third - 1, values.end(), std::greater<>());
  else
    std::nth_element(values.begin(), values.begin() + third - 1, values.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < third; ++i) sum += values[i];
  return sum / static_cast<double>(third);
}

ResponseStatistics ResponseStatisticsAccumulator::result() {
  ResponseStatistics r;
  r.samples = moments_.count();
  r.time_step = options_.time_step;
  r.duration = options_.duration;
  r.mean = moments_.mean();
  r.standard_deviation = moments_.standard_deviation();
  r.minimum = moments_.minimum();
  r.maximum = moments_.maximum();
  r.skewness = moments_.skewness();
  r.kurtosis = moments_.kurtosis();
  r.mean_plus_4_sigma = r.mean + 4.0 * r.standard_deviation;
  r.mean_minus_4_sigma = r.mean - 4.0 * r.standard_deviation;
  if (r.samples == 0) return r;
  if (!options_.cycles) return with_spectrum(r);

  Cycles cycles = zero_upcrossing_cycles(turning_points_.values(), r.mean);
  r.upcrossings = cycles.upcrossings;
  r.crests = std::move(cycles.crests);
  r.troughs = std::move(cycles.troughs);
  // Rice's rate of mean up-crossings nu0 = count / record duration; Tz = 1 / nu0.
  const double record_duration = static_cast<double>(r.samples - 1) * options_.time_step;
  if (r.upcrossings > 0) r.zero_upcrossing_period = record_duration / static_cast<double>(r.upcrossings);
  r.significant_crest = mean_of_extreme_third(r.crests, true);
  r.significant_trough = mean_of_extreme_third(r.troughs, false);

  // Peaks in the record: the complete cycles; in D: D / Tz.
  const double record_peaks = static_cast<double>(r.crests.size());
  r.cycles_in_duration = options_.duration / r.zero_upcrossing_period;
  auto rayleigh = [&r](double n, double sign) {
    return n > 1.0 ? r.mean + sign * r.standard_deviation * std::sqrt(2.0 * std::log(n)) : ResponseStatistics::nan;
  };
  r.rayleigh = {rayleigh(record_peaks, 1.0), rayleigh(r.cycles_in_duration, 1.0)};
  r.rayleigh_minimum = {rayleigh(record_peaks, -1.0), rayleigh(r.cycles_in_duration, -1.0)};

  if (!options_.extreme_value_fits) return with_spectrum(r);
  std::vector<double> excursions(r.crests.size());
  for (std::size_t i = 0; i < excursions.size(); ++i) excursions[i] = r.crests[i] - r.mean;
  r.weibull = fit_weibull(excursions);
  if (std::isfinite(r.weibull.shape))
    r.weibull_maximum = {r.mean + r.weibull.level_exceeded_once_in(record_peaks),
                         r.mean + r.weibull.level_exceeded_once_in(r.cycles_in_duration)};

  if (excursions.size() >= 3) {
    // Threshold: the excursion exceeded by the chosen fraction of the peaks.
    std::vector<double> sorted = excursions;
    std::sort(sorted.begin(), sorted.end());
    const auto above = static_cast<std::size_t>(std::floor(options_.threshold_fraction * sorted.size()));
    if (above > 0 && above < sorted.size()) {
      const double threshold = sorted[sorted.size() - above - 1];
      r.pareto = fit_generalized_pareto(excursions, threshold);
      if (std::isfinite(r.pareto.shape)) {
        // Exceedances expected among n peaks: n * (exceedances / peaks).
        const double rate = static_cast<double>(r.pareto.exceedances) / record_peaks;
        r.pareto_maximum = {r.mean + r.pareto.level_exceeded_once_in(record_peaks * rate),
                            r.mean + r.pareto.level_exceeded_once_in(r.cycles_in_duration * rate)};
      }
    }
  }

  return with_spectrum(r);
}

ResponseStatistics& ResponseStatisticsAccumulator::with_spectrum(ResponseStatistics& r) const {
  if (welch_ && welch_->segments() > 0) {
    r.frequencies = welch_->frequencies();
    r.density = welch_->density();
    r.spectrum = spectral_moments(r.frequencies, r.density);
  }
  return r;
}

ResponseStatistics response_statistics(const double* x, std::int64_t n, const StatisticsOptions& options) {
  ResponseStatisticsAccumulator accumulator(options, n);
  for (std::int64_t i = 0; i < n; ++i) accumulator.add(x[i]);
  return accumulator.result();
}

}  // namespace heavesim::stats
