// Response statistics (signal/) against closed forms written here: trigonometric signals
// whose moments, crossings and crests are known exactly, maxima of Rayleigh peaks,
// samples of Weibull and generalised Pareto laws with known parameters, spectra of white
// noise, a sine and a JONSWAP sea. Random inputs come from tests/signal/random_signals.hpp
// (fixed seeds: deterministic).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "signal/moment_accumulator.hpp"
#include "signal/response_statistics.hpp"
#include "tests/signal/random_signals.hpp"

namespace heavesim::stats {
namespace {

using testing::RandomSource;
constexpr double pi = std::numbers::pi;
constexpr double euler_gamma = 0.57721566490153286;

StatisticsOptions without_spectrum(double dt) {
  StatisticsOptions options;
  options.time_step = dt;
  options.segment_length = -1;
  return options;
}

// x = sin(theta) + 0.3 sin(3 theta) = sin(theta) (1.9 - 1.2 sin^2 theta) is zero only
// where sin(theta) = 0, so it up-crosses its mean (0) once a period T; its crest is
// where 1.9 = 3.6 sin^2: x_max = (2/3) 1.9 sqrt(1.9 / 3.6).
TEST(ResponseStatistics, SumOfSinesHasOneUpcrossingAPeriodAndItsClosedFormCrest) {
  const double period = 10.0, dt = 0.01;
  const int periods = 40;
  const int n = static_cast<int>(std::lround(periods * period / dt));  // whole periods: mean 0 to round-off
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) {
    const double theta = 0.3 + 2.0 * pi * i * dt / period;  // no sample at a crossing
    x[i] = std::sin(theta) + 0.3 * std::sin(3.0 * theta);
  }
  const ResponseStatistics r = response_statistics(x, without_spectrum(dt));
  EXPECT_NEAR(r.mean, 0.0, 1e-14);
  EXPECT_EQ(r.upcrossings, periods);           // at theta = 2 pi j, j = 1 .. 40
  EXPECT_EQ(r.crests.size(), std::size_t(periods - 1));  // complete cycles between them
  // Tz = record / count: the record holds 40 periods less one step.
  EXPECT_NEAR(r.zero_upcrossing_period, period, dt / periods + 1e-12);
  // Sampled crest: below the true one by at most |x''|_max (dt/2)^2 / 2, with
  // |x''| <= (2 pi / T)^2 (1 + 0.3 * 9).
  const double crest = (2.0 / 3.0) * 1.9 * std::sqrt(1.9 / 3.6);
  const double sampling = 0.5 * 3.7 * std::pow(2.0 * pi / period * dt / 2.0, 2);
  for (double c : r.crests) EXPECT_NEAR(c, crest - sampling / 2, sampling / 2 + 1e-12);
  for (double t : r.troughs) EXPECT_NEAR(t, -crest + sampling / 2, sampling / 2 + 1e-12);
  EXPECT_NEAR(r.significant_crest, crest, sampling + 1e-12);
  // Variance of the sum of orthogonal sines: (1 + 0.09) / 2 (population); sample std uses n - 1.
  EXPECT_NEAR(r.standard_deviation, std::sqrt(1.09 / 2.0 * n / (n - 1.0)), 1e-12);
  EXPECT_NEAR(r.mean_plus_4_sigma, 4.0 * r.standard_deviation, 1e-12);
}

// Moments over whole periods are exact (discrete orthogonality of trigonometric
// polynomials of degree below the sample count): for a sine, m4 / m2^2 = (3/8) / (1/2)^2 =
// 1.5 and no skewness; for x = cos(theta) + 0.5 cos(2 theta), E x^2 = 5/8 and
// E x^3 = 3 E[cos^2(theta) 0.5 cos(2 theta)] = 3/8, so g1 = (3/8) / (5/8)^(3/2).
TEST(ResponseStatistics, MomentsOfTrigonometricSignalsMatchTheirClosedForms) {
  const int n = 1000;
  std::vector<double> sine(n), skewed(n);
  for (int i = 0; i < n; ++i) {
    const double theta = 2.0 * pi * i / 100.0;  // 10 whole periods
    sine[i] = 2.0 * std::sin(theta) + 5.0;
    skewed[i] = std::cos(theta) + 0.5 * std::cos(2.0 * theta);
  }
  const ResponseStatistics s = response_statistics(sine, without_spectrum(0.1));
  EXPECT_NEAR(s.mean, 5.0, 1e-13);
  EXPECT_NEAR(s.skewness, 0.0, 1e-12);
  EXPECT_NEAR(s.kurtosis, 1.5, 1e-12);
  EXPECT_NEAR(s.minimum, 3.0, 1e-12);
  EXPECT_NEAR(s.maximum, 7.0, 1e-12);
  const ResponseStatistics k = response_statistics(skewed, without_spectrum(0.1));
  EXPECT_NEAR(k.skewness, 0.375 / std::pow(0.625, 1.5), 1e-12);
  EXPECT_NEAR(k.standard_deviation, std::sqrt(0.625 * n / (n - 1.0)), 1e-12);
}

// The same signal as blocks of samples, as the recorder adds them (every third value of
// an interleaved array, blocks of 7, 1024, 1024 and the rest after single samples), on a
// mean of 1e4 that the central moments must not see. Closed forms over whole periods:
// E[x^2] = 1/2 + 1/8, E[x^3] = 3 E[cos^2 t cos 2t] / 2 = 3/8, E[x^4] = 3/8 + 6/16 + 3/128
// (kurtosis 1.98).
TEST(ResponseStatistics, MomentsOfBlocksMatchTheClosedFormsAndTheOneAtATimeUpdate) {
  const int n = 3000, stride = 3;  // 30 whole periods
  std::vector<double> interleaved(n * stride, -7.0);
  for (int i = 0; i < n; ++i) {
    const double theta = 2.0 * pi * i / 100.0;
    interleaved[i * stride] = 1e4 + std::cos(theta) + 0.5 * std::cos(2.0 * theta);
  }
  MomentAccumulator blocks, one_at_a_time;
  for (int i = 0; i < 3; ++i) blocks.add(interleaved[i * stride]);
  int first = 3;
  for (int size : {7, 1024, 1024, n}) {
    const int count = std::min(size, n - first);
    blocks.add(interleaved.data() + first * stride, stride, count);
    first += count;
  }
  blocks.add(interleaved.data(), stride, 0);  // an empty block changes nothing
  for (int i = 0; i < n; ++i) one_at_a_time.add(interleaved[i * stride]);
  ASSERT_EQ(blocks.count(), n);
  const double variance = 0.625, third = 0.375, fourth = 0.375 + 0.375 + 3.0 / 128.0;
  for (const MomentAccumulator* m : {&blocks, &one_at_a_time}) {
    // Round-off: a sum of 3000 values of 1e4 (bounded by n eps |x| = 7e-9; 1.8e-11 is
    // measured), deviations of values of 1e4 known to 2e-12 each.
    EXPECT_NEAR(m->mean(), 1e4, 1e-9);
    EXPECT_NEAR(m->standard_deviation(), std::sqrt(variance * n / (n - 1.0)), 1e-10);
    EXPECT_NEAR(m->skewness(), third / std::pow(variance, 1.5), 1e-10);
    EXPECT_NEAR(m->kurtosis(), fourth / (variance * variance), 1e-10);
    EXPECT_EQ(m->minimum(), *std::min_element(interleaved.begin(), interleaved.end(), [](double a, double b) {
      return (a == -7.0 ? 1e9 : a) < (b == -7.0 ? 1e9 : b);
    }));
  }
}

// The recorder's block statistics (MomentAccumulator::add_rows): eleven interleaved
// columns (two tiles of eight), column c the signal above times (c + 1) on a mean of
// 1e4 (c - 5), added as blocks of 1, 1024, 1024 and the rest. Every column against the
// same closed forms (skewness and kurtosis do not depend on the scale), its extremes
// exactly, and against the column added alone through the strided path (two algorithms).
TEST(ResponseStatistics, RowsOfManyColumnsMatchTheClosedFormsColumnByColumn) {
  const int n = 3000, width = 11;  // 30 whole periods
  std::vector<double> rows(n * width);
  for (int i = 0; i < n; ++i) {
    const double theta = 2.0 * pi * i / 100.0;
    for (int c = 0; c < width; ++c)
      rows[i * width + c] = 1e4 * (c - 5) + (c + 1) * (std::cos(theta) + 0.5 * std::cos(2.0 * theta));
  }
  std::vector<MomentAccumulator> by_rows(width), by_column(width);
  int first = 0;
  for (int size : {1, 1024, 1024, n}) {
    const int count = std::min(size, n - first);
    MomentAccumulator::add_rows(by_rows.data(), width, rows.data() + first * width, count);
    first += count;
  }
  MomentAccumulator::add_rows(by_rows.data(), width, rows.data(), 0);  // an empty block changes nothing
  for (int c = 0; c < width; ++c) by_column[c].add(rows.data() + c, width, n);
  const double variance = 0.625, third = 0.375, fourth = 0.375 + 0.375 + 3.0 / 128.0;
  for (int c = 0; c < width; ++c) {
    const MomentAccumulator& m = by_rows[c];
    const double scale = c + 1.0;
    ASSERT_EQ(m.count(), n);
    // Round-off: a block's mean of 1024 values of |offset| is off by some sqrt(1024) eps
    // |offset| (a random walk), and the central sums about it shift the skewness and
    // kurtosis by ~3 and ~4 times that over sigma = 0.79 (c + 1): 1.5e-14 |offset| / (c + 1),
    // bounded here with a factor 4 (column 0, |offset| = 5e4 on a unit spread: 4.5e-10 is
    // measured, and 1.4e-9 for the strided path it replaces).
    const double offset = std::abs(1e4 * (c - 5)), moment_error = 1e-10 + 6e-14 * offset / scale;
    EXPECT_NEAR(m.mean(), 1e4 * (c - 5), 5e-9) << "column " << c;
    EXPECT_NEAR(m.standard_deviation(), scale * std::sqrt(variance * n / (n - 1.0)), moment_error * scale) << "column " << c;
    EXPECT_NEAR(m.skewness(), third / std::pow(variance, 1.5), moment_error) << "column " << c;
    EXPECT_NEAR(m.kurtosis(), fourth / (variance * variance), moment_error) << "column " << c;
    double minimum = rows[c], maximum = rows[c];
    for (int i = 0; i < n; ++i) {
      minimum = std::min(minimum, rows[i * width + c]);
      maximum = std::max(maximum, rows[i * width + c]);
    }
    EXPECT_EQ(m.minimum(), minimum) << "column " << c;
    EXPECT_EQ(m.maximum(), maximum) << "column " << c;
    // The two paths sum in different orders: they agree to both their round-offs.
    EXPECT_NEAR(m.mean(), by_column[c].mean(), 1e-10 * std::abs(m.mean()) + 1e-12) << "column " << c;
    EXPECT_NEAR(m.skewness(), by_column[c].skewness(), 2.0 * moment_error) << "column " << c;
    EXPECT_NEAR(m.kurtosis(), by_column[c].kurtosis(), 2.0 * moment_error) << "column " << c;
  }
}

// add_rows takes each tile width through its own compiled path (1, 2, 3, 4, 6, 8 fixed,
// others at run time), each column still summed row after row: for every width from 1 to
// 17, each column's moments equal, bit for bit, those of the same values added as a
// one-column block, and that column's mean is the plain sum of its values over n (the
// test's own loop, in the same order), its extremes the plain minimum and maximum.
TEST(ResponseStatistics, EveryTileWidthGivesTheOneColumnMomentsBitForBit) {
  const int n = 700;
  for (int width = 1; width <= 17; ++width) {
    std::vector<double> rows(n * width);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < width; ++c)
        rows[i * width + c] = 100.0 * c + std::sin(0.37 * i + c) + 0.25 * std::cos(1.3 * i * (c + 1));
    std::vector<MomentAccumulator> by_rows(width);
    MomentAccumulator::add_rows(by_rows.data(), width, rows.data(), 400);
    MomentAccumulator::add_rows(by_rows.data(), width, rows.data() + 400 * width, n - 400);
    for (int c = 0; c < width; ++c) {
      std::vector<double> column(n);
      double sum = 0.0;
      for (int i = 0; i < n; ++i) column[i] = rows[i * width + c];
      MomentAccumulator alone;
      MomentAccumulator::add_rows(&alone, 1, column.data(), 400);
      MomentAccumulator::add_rows(&alone, 1, column.data() + 400, n - 400);
      const MomentAccumulator& m = by_rows[c];
      EXPECT_EQ(m.mean(), alone.mean()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.standard_deviation(), alone.standard_deviation()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.skewness(), alone.skewness()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.kurtosis(), alone.kurtosis()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.minimum(), *std::min_element(column.begin(), column.end())) << "width " << width;
      EXPECT_EQ(m.maximum(), *std::max_element(column.begin(), column.end())) << "width " << width;
      MomentAccumulator whole;
      MomentAccumulator::add_rows(&whole, 1, column.data(), n);
      for (int i = 0; i < n; ++i) sum += column[i];
      EXPECT_EQ(whole.mean(), sum / n) << "width " << width << ", column " << c;
    }
  }
}

// Blocks added up to the second order (the recorder's whole-record statistics before the
// evaluation window) give every column the extremes, mean and standard deviation of the
// full path, bit for bit, the deviation also within round-off of the test's own two-pass
// sum, and no skewness or kurtosis, even once a full accumulator is merged in.
TEST(ResponseStatistics, SecondOrderBlocksKeepTheMeanAndDeviationAndReportNoHigherMoment) {
  const int n = 900;
  for (int width : {1, 3, 5, 6, 11}) {
    std::vector<double> rows(n * width);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < width; ++c) rows[i * width + c] = 10.0 * c + std::sin(0.21 * i + c) + 0.5 * std::cos(0.9 * i);
    std::vector<MomentAccumulator> full(width), second(width);
    for (int first = 0; first < n; first += 256) {
      const int count = std::min(256, n - first);
      MomentAccumulator::add_rows(full.data(), width, rows.data() + first * width, count);
      MomentAccumulator::add_rows(second.data(), width, rows.data() + first * width, count,
                                  MomentAccumulator::Orders::up_to_second);
    }
    for (int c = 0; c < width; ++c) {
      double sum = 0.0, squares = 0.0;
      for (int i = 0; i < n; ++i) sum += rows[i * width + c];
      const double mean = sum / n;
      for (int i = 0; i < n; ++i) squares += (rows[i * width + c] - mean) * (rows[i * width + c] - mean);
      const MomentAccumulator& m = second[c];
      EXPECT_EQ(m.count(), n);
      EXPECT_EQ(m.mean(), full[c].mean()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.standard_deviation(), full[c].standard_deviation()) << "width " << width << ", column " << c;
      EXPECT_EQ(m.minimum(), full[c].minimum());
      EXPECT_EQ(m.maximum(), full[c].maximum());
      EXPECT_NEAR(m.standard_deviation(), std::sqrt(squares / (n - 1)), 1e-13) << "width " << width;
      EXPECT_TRUE(std::isfinite(full[c].skewness()) && std::isfinite(full[c].kurtosis()));
      EXPECT_TRUE(std::isnan(m.skewness()) && std::isnan(m.kurtosis())) << "width " << width;
      MomentAccumulator merged = m;
      merged.merge(full[c]);
      EXPECT_TRUE(std::isnan(merged.skewness()) && std::isnan(merged.kurtosis()));
      MomentAccumulator into_full = full[c];
      into_full.merge(m);
      EXPECT_TRUE(std::isnan(into_full.kurtosis()));
      // The same samples twice: the same mean, M2 doubled over 2n - 1.
      EXPECT_NEAR(into_full.standard_deviation(), std::sqrt(2.0 * squares / (2 * n - 1)), 1e-13);
    }
  }
}

// A column of an interleaved block (the recorder's rows) gives the statistics of the same
// samples stored contiguously: the strided add copies the column, then takes the
// contiguous path. Crossings, crests and the spectrum see the same values in the same
// order, bit for bit; the moments' vectorised sums start on the copy's alignment instead
// of the original's, so they agree to round-off.
TEST(ResponseStatistics, ColumnOfInterleavedRowsGivesTheContiguousStatisticsExactly) {
  const int n = 10000, stride = 5;
  StatisticsOptions options;
  options.time_step = 0.05;
  options.duration = 3.0 * 3600.0;
  RandomSource random(11);
  std::vector<double> contiguous(n), interleaved(n * stride, 99.0);
  for (int i = 0; i < n; ++i) {
    contiguous[i] = std::sin(2.0 * pi * i * 0.05 / 9.0) + 0.2 * random.normal();
    interleaved[i * stride + 2] = contiguous[i];
  }
  ResponseStatisticsAccumulator from_rows(options, n), from_column(options, n);
  int first = 0;
  for (int size : {3, 1024, 1024, 5000, n}) {  // the recorder's blocks, and one longer than a run copied at once
    const int count = std::min(size, n - first);
    from_rows.add(interleaved.data() + first * stride + 2, stride, count);
    from_column.add(contiguous.data() + first, 1, count);
    first += count;
  }
  const ResponseStatistics a = from_rows.result(), b = from_column.result();
  ASSERT_EQ(a.samples, n);
  EXPECT_NEAR(a.mean, b.mean, 1e-15 * n);
  EXPECT_NEAR(a.standard_deviation, b.standard_deviation, 1e-14 * b.standard_deviation);
  EXPECT_NEAR(a.skewness, b.skewness, 1e-12);
  EXPECT_NEAR(a.kurtosis, b.kurtosis, 1e-12);
  EXPECT_EQ(a.upcrossings, b.upcrossings);
  EXPECT_EQ(a.crests, b.crests);
  EXPECT_EQ(a.significant_crest, b.significant_crest);
  EXPECT_GT(a.spectrum.m0, 0.0);
  EXPECT_EQ(a.density, b.density);
}

// Peaks that are exactly independent Rayleigh (sigma = 1): each cycle one period of
// a_j sin, sampled 8 times a cycle so that its crest a_j is a sample. The signal's
// variance is E[a^2] / 2 = sigma^2, as for a narrow-band Gaussian process. Over
// R = 10^4 records of N = 200 cycles:
//  * the mean of the largest crest approaches sigma (sqrt(2 ln N) + gamma / sqrt(2 ln N))
//    (Cartwright & Longuet-Higgins 1956, from the Gumbel limit), whose own error at
//    N = 200 (against the exact E[max] = int 1 - F(x)^N dx, by quadrature here) is
//    below 0.03 sigma; the sampling error is the Gumbel standard deviation
//    pi / (sqrt 6 sqrt(2 ln N)) / sqrt(R) ~ 0.0038 sigma: 4 of it;
//  * the code's Rayleigh MPM over the record, F^-1(1 - 1/N), is exceeded by the record
//    maximum with probability 1 - (1 - 1/N)^N = 0.634; binomial standard error
//    sqrt(p (1 - p) / R) = 0.0048: 4 of it, plus 0.005 for sigma estimated from the record.
TEST(ResponseStatistics, LargestOfRayleighPeaksMatchesTheCartwrightLonguetHigginsMean) {
  const int records = 10000, cycles = 200;
  const double a = std::sqrt(2.0 * std::log(static_cast<double>(cycles)));
  RandomSource random(20261124);
  std::vector<double> x(cycles * 8 + 2);
  double sum_maximum = 0.0;
  int exceeded = 0;
  for (int r = 0; r < records; ++r) {
    x.front() = -1.0;  // starts below: the first cycle is complete
    for (int j = 0; j < cycles; ++j) {
      const double amplitude = std::sqrt(-2.0 * std::log(random.uniform()));
      for (int i = 0; i < 8; ++i) x[1 + j * 8 + i] = amplitude * std::sin(2.0 * pi * i / 8.0);
    }
    x.back() = 0.5;  // ends above: the last cycle is complete
    StatisticsOptions options = without_spectrum(1.0);
    options.extreme_value_fits = false;  // 10^4 records: the Rayleigh model only
    const ResponseStatistics s = response_statistics(x, options);
    ASSERT_EQ(s.crests.size(), std::size_t(cycles));
    const double largest = *std::max_element(s.crests.begin(), s.crests.end());
    sum_maximum += largest - s.mean;
    exceeded += largest > s.rayleigh.record ? 1 : 0;
  }
  const double mean_maximum = sum_maximum / records;
  double exact = 0.0;  // E[max] by the trapezoidal rule on [0, 12] (the integrand < 1e-28 beyond)
  const int steps = 120000;
  for (int i = 0; i <= steps; ++i) {
    const double y = 12.0 * i / steps;
    const double f = 1.0 - std::pow(1.0 - std::exp(-0.5 * y * y), cycles);
    exact += (i == 0 || i == steps ? 0.5 : 1.0) * f * 12.0 / steps;
  }
  const double sampling = pi / std::sqrt(6.0) / a / std::sqrt(static_cast<double>(records));
  EXPECT_NEAR(mean_maximum, exact, 4.0 * sampling);
  EXPECT_NEAR(mean_maximum, a + euler_gamma / a, 4.0 * sampling + 0.03);
  const double p = 1.0 - std::pow(1.0 - 1.0 / cycles, cycles);
  EXPECT_NEAR(static_cast<double>(exceeded) / records, p, 4.0 * std::sqrt(p * (1 - p) / records) + 0.005);
}

/// A periodic Gaussian signal of n samples whose one-sided density is `density(f)`
/// (units^2/Hz): Fourier coefficients with independent Gaussian real and imaginary parts
/// (a Gaussian process, not only asymptotically) made real by Eigen's inverse FFT.
template <class Density>
std::vector<double> gaussian_signal(int n, double dt, const Density& density, RandomSource& random,
                                    double* variance = nullptr) {
  const double df = 1.0 / (n * dt);
  std::vector<std::complex<double>> coefficients(n / 2 + 1);
  double expected = 0.0;
  for (int k = 1; k < n / 2; ++k) {
    const double s = density(k * df);
    // The component's amplitude a_k = |c_k| / (n/2) has E a_k^2 / 2 = s df, so each part
    // of c_k has the variance (n/2)^2 s df.
    const double scale = 0.5 * n * std::sqrt(s * df);
    coefficients[k] = {scale * random.normal(), scale * random.normal()};
    expected += s * df;
  }
  if (variance) *variance = expected;
  std::vector<double> x;
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  fft.inv(x, coefficients, n);
  return x;
}

// A narrow-band Gaussian process (flat density on 0.9 f0 .. 1.1 f0, epsilon = 0.114):
// its crests between mean up-crossings are Rayleigh with the process's sigma
// (Rice 1945; Cartwright & Longuet-Higgins 1956 for epsilon -> 0): Weibull shape 2, scale
// sqrt(2) sigma. About 13,000 cycles, but the envelope decorrelates over ~1 / (0.2 f0) =
// 5 cycles: ~2,600 independent crests, so the maximum-likelihood standard errors
// 0.78 k / sqrt(n) = 0.031 (shape) and 1.05 lambda / (k sqrt(n)) = 1.0 % of lambda (scale).
TEST(ResponseStatistics, CrestsOfANarrowBandGaussianProcessAreRayleigh) {
  const int n = 1 << 18;
  const double dt = 0.05, f0 = 1.0;  // 20 samples a period
  RandomSource random(7);
  const std::vector<double> x =
      gaussian_signal(n, dt, [f0](double f) { return f >= 0.9 * f0 && f <= 1.1 * f0 ? 1.0 : 0.0; }, random);
  StatisticsOptions options;
  options.time_step = dt;
  const ResponseStatistics r = response_statistics(x, options);
  const double sigma = r.standard_deviation;
  EXPECT_NEAR(r.weibull.shape, 2.0, 4.0 * 0.031);
  EXPECT_NEAR(r.weibull.scale / (std::sqrt(2.0) * sigma), 1.0, 4.0 * 0.010);
  // Gaussian moments, n_eff ~ 2 x 0.2 f0 x record = 5,200: SE sqrt(6/n), sqrt(24/n).
  EXPECT_NEAR(r.skewness, 0.0, 4.0 * std::sqrt(6.0 / 5200));
  EXPECT_NEAR(r.kurtosis, 3.0, 4.0 * std::sqrt(24.0 / 5200));
  // Rice: Tz = sqrt(m0 / m2), by crossings and by the Welch moments (two algorithms):
  // for the flat band sqrt(m2 / m0) = f0 sqrt((1.1^3 - 0.9^3) / (3 * 0.2)).
  const double tz = 1.0 / (f0 * std::sqrt((std::pow(1.1, 3) - std::pow(0.9, 3)) / 0.6));
  EXPECT_NEAR(r.zero_upcrossing_period / tz, 1.0, 0.01);
  EXPECT_NEAR(r.spectrum.zero_upcrossing_period() / tz, 1.0, 0.01);
  const double m0 = 0.2, m2 = (std::pow(1.1, 3) - std::pow(0.9, 3)) / 3, m4 = (std::pow(1.1, 5) - std::pow(0.9, 5)) / 5;
  EXPECT_NEAR(r.spectrum.bandwidth(), std::sqrt(1.0 - m2 * m2 / (m0 * m4)), 0.03);
}

// Weibull samples by inversion, y = lambda (-ln u)^(1/k); the maximum-likelihood
// estimates' asymptotic standard deviations are 0.780 k / sqrt(n) and
// 1.053 lambda / (k sqrt(n)) (Cohen 1965): within 4 of them; and the Kolmogorov-Smirnov
// statistic of the fitted law below the 1 % critical value 1.63 / sqrt(n).
TEST(ExtremeValueFits, WeibullFitRecoversTheShapeAndScaleOfItsSamples) {
  const int n = 2000;
  RandomSource random(11);
  for (const auto& [shape, scale] : {std::pair{1.7, 2.5}, std::pair{2.0, 0.3}, std::pair{0.8, 40.0}}) {
    std::vector<double> y(n);
    for (double& v : y) v = scale * std::pow(-std::log(random.uniform()), 1.0 / shape);
    const WeibullFit fit = fit_weibull(y);
    EXPECT_NEAR(fit.shape, shape, 4.0 * 0.780 * shape / std::sqrt(n));
    EXPECT_NEAR(fit.scale, scale, 4.0 * 1.053 * scale / (shape * std::sqrt(n)));
    EXPECT_LT(fit.ks_statistic, 1.63 / std::sqrt(n));
    EXPECT_NEAR(fit.level_exceeded_once_in(1000.0), fit.scale * std::pow(std::log(1000.0), 1.0 / fit.shape), 1e-12);
  }
}

// Generalised Pareto samples by inversion, y = sigma ((u^-xi) - 1) / xi (y = -sigma ln u
// for xi = 0), shifted by a threshold; the MLE's asymptotic variances are (1 + xi)^2 / n
// and 2 sigma^2 (1 + xi) / n (Coles 2001, sec. 4.3.3, for xi > -0.5).
TEST(ExtremeValueFits, GeneralizedParetoFitRecoversShapeAndScaleOverTheThreshold) {
  const int n = 3000;
  const double threshold = 1.2;
  RandomSource random(13);
  for (const auto& [xi, sigma] : {std::pair{0.2, 1.5}, std::pair{-0.2, 0.7}, std::pair{0.0, 2.0}}) {
    std::vector<double> data(n);
    for (double& v : data) {
      const double u = random.uniform();
      v = threshold + (xi == 0.0 ? -sigma * std::log(u) : sigma * (std::pow(u, -xi) - 1.0) / xi);
    }
    data.push_back(threshold - 0.5);  // below the threshold: not an exceedance
    const GeneralizedParetoFit fit = fit_generalized_pareto(data, threshold);
    EXPECT_EQ(fit.exceedances, n);
    EXPECT_NEAR(fit.shape, xi, 4.0 * (1.0 + xi) / std::sqrt(n));
    EXPECT_NEAR(fit.scale, sigma, 4.0 * sigma * std::sqrt(2.0 * (1.0 + xi) / n));
    EXPECT_LT(fit.ks_statistic, 1.63 / std::sqrt(n));
    // The fit is the likelihood's maximum: both scores of
    //   l(xi, sigma) = -n ln sigma - (1 + 1/xi) sum ln(1 + xi y / sigma)
    // vanish there (Coles 2001, eq. 4.10), written out here apart from the fit's search.
    if (xi != 0.0) {
      double sum_log = 0.0, sum_ratio = 0.0;
      for (double v : data) {
        if (v <= threshold) continue;
        const double z = (v - threshold) / fit.scale;
        sum_log += std::log1p(fit.shape * z);
        sum_ratio += z / (1.0 + fit.shape * z);
      }
      const double score_scale = -n + (1.0 + fit.shape) * sum_ratio;  // sigma dl/dsigma
      const double score_shape = sum_log / (fit.shape * fit.shape) - (1.0 + 1.0 / fit.shape) * sum_ratio;
      EXPECT_LT(std::abs(score_scale) / n, 1e-7) << "xi " << xi;
      EXPECT_LT(std::abs(score_shape) / n, 1e-7) << "xi " << xi;
    }
  }
}

// White noise of variance s2 sampled at fs has the flat one-sided density s2 / (fs / 2).
// Each bin of a Welch estimate with K half-overlapping Hann segments has a relative
// standard deviation close to 1 / sqrt(0.95 K) (Welch 1967; Harris 1978): here K = 1023,
// 0.032; the mean over the 127 interior bins has about 1/sqrt(127) of it.
TEST(WelchSpectrum, WhiteNoiseHasTheFlatDensityOfItsVariance) {
  const int n = 1 << 17, segment = 256;
  const double fs = 10.0, variance = 4.0;
  RandomSource random(3);
  WelchAccumulator welch(segment, fs);
  double sum_squares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = 2.0 * random.normal();
    sum_squares += v * v;
    welch.add(v);
  }
  EXPECT_EQ(welch.segments(), 2 * n / segment - 1);
  const std::vector<double> s = welch.density();
  ASSERT_EQ(s.size(), std::size_t(segment / 2 + 1));
  const double flat = variance / (fs / 2.0), bin_error = 1.0 / std::sqrt(0.95 * welch.segments());
  double mean = 0.0;
  for (int k = 1; k < segment / 2; ++k) {
    EXPECT_NEAR(s[k] / flat, 1.0, 5.0 * bin_error) << "bin " << k;
    mean += s[k] / (segment / 2 - 1);
  }
  EXPECT_NEAR(mean / flat, 1.0, 4.0 * bin_error / std::sqrt(segment / 2 - 1.0) + 0.002);
  // Parseval: m0 is the variance (the sample's, to the bin-mean's error).
  EXPECT_NEAR(welch.moments().m0 / (sum_squares / n), 1.0, 4.0 * bin_error / std::sqrt(segment / 2 - 1.0) + 0.01);
}

// Samples added as runs (the recorder's columns) fill the same half-overlapping segments
// as samples added one at a time: the same density, bit for bit, whatever the runs' lengths
// against the segment's (shorter, longer, ending on a segment's end).
TEST(WelchSpectrum, RunsOfSamplesFillTheSameSegmentsAsSingleSamples) {
  const int segment = 64, n = 1000;
  RandomSource random(5);
  std::vector<double> x(n);
  for (double& v : x) v = random.normal();
  WelchAccumulator by_runs(segment, 2.0), by_sample(segment, 2.0);
  int first = 0;
  for (int size : {1, 31, 32, 200, 0, 64, 7, n}) {
    const int count = std::min(size, n - first);
    by_runs.add(x.data() + first, count);
    first += count;
  }
  for (double v : x) by_sample.add(v);
  EXPECT_EQ(by_runs.segments(), 2 * n / segment - 1);  // whole segments: (n - L/2) / (L/2)
  EXPECT_EQ(by_runs.segments(), by_sample.segments());
  EXPECT_EQ(by_runs.density(), by_sample.density());
}

// Before its first whole segment an accumulator has its frequencies f_k = k fs / L
// (k = 0 .. L/2) and no density; its buffers are made by the first sample (an accumulator
// per recorded column is made before the run), which must not change what a segment holds:
// a constant's density is L/2 + 1 zeros (that the sums grow with a signal's power is
// the white-noise and sine tests' business).
TEST(WelchSpectrum, BeforeTheFirstSegmentFrequenciesButNoDensity) {
  const int segment = 16;
  const double fs = 8.0;
  WelchAccumulator welch(segment, fs);
  std::vector<double> f = welch.frequencies();
  ASSERT_EQ(f.size(), std::size_t(segment / 2 + 1));
  EXPECT_EQ(f[0], 0.0);
  EXPECT_DOUBLE_EQ(f[segment / 2], fs / 2.0);
  EXPECT_TRUE(welch.density().empty());
  welch.add(nullptr, 0);  // nothing added: still nothing
  for (int i = 0; i < segment - 1; ++i) welch.add(1.0);
  EXPECT_EQ(welch.segments(), 0);
  EXPECT_TRUE(welch.density().empty());
  welch.add(1.0);  // a constant: its mean removed, nothing left in any bin
  EXPECT_EQ(welch.segments(), 1);
  ASSERT_EQ(welch.density().size(), std::size_t(segment / 2 + 1));
  for (double s : welch.density()) EXPECT_EQ(s, 0.0);
}

// A sine on a bin f0 = k0 fs / L: the periodic Hann window leaks it into bins k0 - 1,
// k0, k0 + 1 only (its transform is 0 at every other bin), and Parseval puts exactly
// A^2 / 2 in them; the density peaks at f0 (Tp = 1 / f0).
TEST(WelchSpectrum, SineOnABinHasItsPowerAndPeriod) {
  const int segment = 128, k0 = 10;
  const double fs = 4.0, amplitude = 3.0, f0 = k0 * fs / segment;
  WelchAccumulator welch(segment, fs);
  for (int i = 0; i < 4096; ++i) welch.add(amplitude * std::sin(2.0 * pi * f0 * i / fs + 0.4));
  const std::vector<double> s = welch.density();
  const double df = fs / segment;
  EXPECT_NEAR((s[k0 - 1] + s[k0] + s[k0 + 1]) * df, amplitude * amplitude / 2.0, 1e-10);
  EXPECT_NEAR(s[k0 - 1] / s[k0], 0.25, 1e-10);  // Hann: half the amplitude one bin away
  EXPECT_LT(s[k0 + 3] * df, 1e-20);
  EXPECT_NEAR(welch.moments().peak_period, 1.0 / f0, 1e-12);
  EXPECT_NEAR(welch.moments().m0, amplitude * amplitude / 2.0, 1e-10);
}

// A JONSWAP sea (DNV-RP-C205 sec. 3.5: gamma 3.3, sigma 0.07 / 0.09) with Tp = 10 s,
// Hs = 3 m: the Welch peak lies within one bin (0.0039 Hz) of 1 / Tp, m0 within its
// estimation error of the integral of the target density, and the spectral Tz agrees with
// the crossing count's (two algorithms) within 3 %.
TEST(WelchSpectrum, JonswapSignalHasItsPeakPeriodAndVariance) {
  const double tp = 10.0, hs = 3.0, dt = 0.5, gamma = 3.3;
  const int n = 1 << 17;
  auto jonswap = [=](double f) {
    const double fp = 1.0 / tp, sigma = f <= fp ? 0.07 : 0.09;
    const double pm = 5.0 / 16.0 * hs * hs * std::pow(fp, 4) * std::pow(f, -5) * std::exp(-1.25 * std::pow(fp / f, 4));
    return (1.0 - 0.287 * std::log(gamma)) * pm *
           std::pow(gamma, std::exp(-0.5 * std::pow((f - fp) / (sigma * fp), 2)));
  };
  RandomSource random(5);
  double variance = 0.0;
  const std::vector<double> x = gaussian_signal(n, dt, jonswap, random, &variance);
  StatisticsOptions options;
  options.time_step = dt;
  options.segment_length = 512;
  const ResponseStatistics r = response_statistics(x, options);
  const double df = 1.0 / (512 * dt);
  EXPECT_NEAR(1.0 / r.spectrum.peak_period, 1.0 / tp, df);
  EXPECT_NEAR(variance, hs * hs / 16.0, 0.05 * hs * hs / 16.0);  // the (1 - 0.287 ln gamma) normalisation
  // K = 511 segments, ~1/sqrt(K) per bin; the sea's ~25 significant bins: ~1 %: 4 of it.
  EXPECT_NEAR(r.spectrum.m0 / variance, 1.0, 0.04);
  EXPECT_NEAR(r.spectrum.zero_upcrossing_period() / r.zero_upcrossing_period, 1.0, 0.03);
}

TEST(ResponseStatistics, ConstantAndShortSignalsGiveNaNNotNonsense) {
  const std::vector<double> flat(100, 2.5);
  const ResponseStatistics r = response_statistics(flat, without_spectrum(0.1));
  EXPECT_EQ(r.upcrossings, 0);
  EXPECT_TRUE(std::isnan(r.zero_upcrossing_period));
  EXPECT_TRUE(std::isnan(r.skewness));
  EXPECT_TRUE(std::isnan(r.rayleigh.duration));
  EXPECT_TRUE(std::isnan(r.weibull.shape));
  EXPECT_EQ(r.maximum, 2.5);
  StatisticsOptions with_spectrum;
  with_spectrum.time_step = 0.1;
  const ResponseStatistics spectral = response_statistics(flat, with_spectrum);
  EXPECT_EQ(spectral.spectrum.m0, 0.0);  // the segment means are removed: nothing left
  EXPECT_TRUE(std::isnan(spectral.spectrum.zero_upcrossing_period()));
  EXPECT_TRUE(std::isnan(spectral.spectrum.bandwidth()));
  EXPECT_TRUE(std::isnan(spectral.spectrum.peak_period));
  EXPECT_THROW(response_statistics(flat, without_spectrum(0.0)), std::invalid_argument);
}

}  // namespace
}  // namespace heavesim::stats
