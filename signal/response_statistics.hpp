#pragma once
// The response statistics of one signal column sampled at a uniform time step: moments,
// zero-up-crossing cycles about the mean, peak and trough statistics, the most probable
// maximum (Rayleigh, Weibull, generalised Pareto) for the record and for a given duration,
// and the Welch spectrum's moments. Definitions and references: docs/physics/statistics.md.
//
// ResponseStatisticsAccumulator takes the samples one at a time (the recorder, no second
// read); response_statistics() runs it over a whole array (`heavesim stats`, tests).
// All quantities are in the signal's own (SI) units, times in s, frequencies in Hz.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "signal/extreme_value_fits.hpp"
#include "signal/moment_accumulator.hpp"
#include "signal/turning_points.hpp"
#include "signal/welch_spectrum.hpp"

namespace heavesim::stats {

struct StatisticsOptions {
  double time_step = 0.0;            // s between samples (> 0)
  double duration = 10800.0;         // s, D of the "over a duration" MPMs (3 h by default)
  /// Welch segment length L (even); 0: the largest power of two <= a quarter of the
  /// record's samples, at most 4096 (at least 7 half-overlapping segments). Negative: no spectrum.
  int segment_length = 0;
  /// The generalised Pareto threshold is the peak excursion exceeded by this fraction of
  /// the peaks (peaks over threshold), -.
  double threshold_fraction = 1.0 / 3.0;
  /// Whether to fit the Weibull and generalised Pareto laws at the end (a few dozen passes
  /// over the crests); without, their fields stay NaN and the rest is unchanged.
  bool extreme_value_fits = true;
  /// Whether to keep the turning points (crossings, crests, troughs, MPMs, fits); without,
  /// only the moments (section 1 of docs/physics/statistics.md) are computed.
  bool cycles = true;
};

/// The most probable maximum of one model, over the record and over the duration D.
struct MostProbableMaximum {
  double record = std::numeric_limits<double>::quiet_NaN();    // units of the signal (absolute)
  double duration = std::numeric_limits<double>::quiet_NaN();  // units of the signal (absolute)
};

struct ResponseStatistics {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::int64_t samples = 0;
  double time_step = nan;  // s
  double mean = nan, standard_deviation = nan, minimum = nan, maximum = nan;  // units
  double skewness = nan;   // g1 = m3 / m2^1.5, -
  double kurtosis = nan;   // m4 / m2^2 (3 for a Gaussian), -
  std::int64_t upcrossings = 0;       // up-crossings of the mean
  double zero_upcrossing_period = nan;  // Tz = record duration / up-crossings, s
  std::vector<double> crests, troughs;  // per complete cycle, absolute, units
  double significant_crest = nan;     // mean of the highest third of the crests, units
  double significant_trough = nan;    // mean of the lowest third of the troughs, units
  double mean_plus_4_sigma = nan;     // mean + 4 std, units
  double mean_minus_4_sigma = nan;    // mean - 4 std, units
  double duration = nan;              // D of the duration MPMs, s
  double cycles_in_duration = nan;    // N = D / Tz, -
  MostProbableMaximum rayleigh;       // mean + sigma sqrt(2 ln N)
  MostProbableMaximum rayleigh_minimum;  // mean - sigma sqrt(2 ln N): the most probable minimum
  WeibullFit weibull;                 // of crest - mean
  MostProbableMaximum weibull_maximum;   // mean + scale (ln N)^(1/shape)
  GeneralizedParetoFit pareto;        // of crest - mean over its threshold
  MostProbableMaximum pareto_maximum;    // mean + u + G^-1(1 - 1/(N p_u))
  SpectralMoments spectrum;           // Welch, Hz moments
  std::vector<double> frequencies, density;  // Hz, units^2/Hz (empty without a spectrum)
};

class ResponseStatisticsAccumulator {
 public:
  /// `record_samples`: the samples expected (only to choose the Welch segment length
  /// when options.segment_length == 0).
  ResponseStatisticsAccumulator(const StatisticsOptions& options, std::int64_t record_samples);
  void add(double x);
  /// The samples x[0], x[stride], ..., x[(count - 1) stride], in time order.
  void add(const double* x, std::ptrdiff_t stride, std::int64_t count);
  std::int64_t samples() const { return moments_.count(); }
  /// The moments (extremes, mean, central sums) of the samples added so far.
  const MomentAccumulator& moments() const { return moments_; }
  /// Everything above; the fits run here (cost: a few passes over the crests).
  ResponseStatistics result();

 private:
  /// Adds the Welch density and its moments to `r`.
  ResponseStatistics& with_spectrum(ResponseStatistics& r) const;
  StatisticsOptions options_;
  MomentAccumulator moments_;
  TurningPoints turning_points_;
  std::optional<WelchAccumulator> welch_;
};

/// The Welch segment length chosen for a record of `samples` (see StatisticsOptions).
int default_segment_length(std::int64_t samples);

/// The statistics of samples x[0..n) (time step options.time_step).
ResponseStatistics response_statistics(const double* x, std::int64_t n, const StatisticsOptions& options);
inline ResponseStatistics response_statistics(const std::vector<double>& x, const StatisticsOptions& options) {
  return response_statistics(x.data(), static_cast<std::int64_t>(x.size()), options);
}

/// Mean of the highest (largest = true) or lowest third of `values` (NaN if fewer than 3).
double mean_of_extreme_third(std::vector<double> values, bool largest);

}  // namespace heavesim::stats
