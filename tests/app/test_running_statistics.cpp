// The recorder's whole-record statistics (app/output/running_statistics.hpp), taken a
// sample at a time and a block at a time, against the two-pass formulas written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "app/output/running_statistics.hpp"

namespace heavesim {
namespace {

TEST(RunningStatistics, BlocksAndSamplesGiveTheTwoPassStatistics) {
  // Three columns with offsets far above their spread (a hook load of 1.6 MN varying by
  // a few kN: the case where a one-pass sum of squares loses every digit), 2600 samples.
  const int columns = 3;
  const long samples = 2600;
  const double offsets[columns] = {0.0, 1.62e6, -3.0e4}, spreads[columns] = {1.0, 4.0e2, 1e-3};
  std::mt19937_64 random(17);
  std::normal_distribution<double> normal;
  std::vector<double> rows(samples * columns);
  for (long k = 0; k < samples; ++k)
    for (int c = 0; c < columns; ++c) rows[k * columns + c] = offsets[c] + spreads[c] * normal(random);

  RunningStatistics by_sample(columns), by_block(columns), mixed(columns);
  for (long k = 0; k < samples; ++k) by_sample.add(&rows[k * columns]);
  // The recorder's blocks: 1024, 1024 and what is left.
  for (long first = 0; first < samples; first += 1024)
    by_block.add_rows(&rows[first * columns], std::min(1024L, samples - first));
  for (long k = 0; k < 7; ++k) mixed.add(&rows[k * columns]);  // a few alone, then blocks of 500
  for (long first = 7; first < samples; first += 500) mixed.add_rows(&rows[first * columns], std::min(500L, samples - first));
  by_block.add_rows(rows.data(), 0);  // an empty block changes nothing

  for (int c = 0; c < columns; ++c) {
    double sum = 0.0, minimum = rows[c], maximum = rows[c];
    for (long k = 0; k < samples; ++k) {
      sum += rows[k * columns + c];
      minimum = std::min(minimum, rows[k * columns + c]);
      maximum = std::max(maximum, rows[k * columns + c]);
    }
    const double mean = sum / samples;
    double squares = 0.0;
    for (long k = 0; k < samples; ++k) squares += std::pow(rows[k * columns + c] - mean, 2);
    const double deviation = std::sqrt(squares / (samples - 1));
    // The column alone, contiguous: a scalar series (the recorder's commonest).
    std::vector<double> column(samples);
    for (long k = 0; k < samples; ++k) column[k] = rows[k * columns + c];
    RunningStatistics scalar(1);
    for (long first = 0; first < samples; first += 1024) scalar.add_rows(&column[first], std::min(1024L, samples - first));
    for (const RunningStatistics* statistics : {&by_sample, &by_block, &mixed, &scalar}) {
      const int i = statistics == &scalar ? 0 : c;
      EXPECT_EQ(statistics->count(), samples);
      EXPECT_EQ(statistics->minimum()[i], minimum);
      EXPECT_EQ(statistics->maximum()[i], maximum);
      // Round-off: the mean, sums of 2600 terms of size |offset|; the deviation, values
      // known to eps |offset| each against a spread (the problem's condition, 3e7 for
      // the third column, where a relative 7.8e-10 is measured).
      const double eps = 2.2e-16;
      EXPECT_NEAR(statistics->mean()[i], mean, 1e-13 * (std::abs(offsets[c]) + spreads[c])) << "column " << c;
      EXPECT_NEAR(statistics->standard_deviation()[i], deviation,
                  (1e-12 + 4.0 * eps * std::abs(offsets[c]) / spreads[c]) * deviation)
          << "column " << c;
    }
  }
}

}  // namespace
}  // namespace heavesim
