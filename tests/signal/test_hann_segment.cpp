// One Welch segment's transform (signal/hann_segment.hpp) against the discrete Fourier
// transform of the mean-removed, Hann-windowed samples written out here, for two lengths
// whose transforms are alive at the same time and share their windows with others of the
// same length (the recorder holds hundreds), and the window's power against its closed
// form sum_n w_n^2 = 3 L / 8 (periodic Hann); the periodogram's sums (add_power) against
// the same DFT's squared magnitudes.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <vector>

#include "signal/hann_segment.hpp"

namespace heavesim::stats {
namespace {

std::vector<std::complex<double>> hann_windowed_dft(const std::vector<double>& x) {
  const int L = static_cast<int>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v / L;
  std::vector<std::complex<double>> X(L / 2 + 1);
  for (int k = 0; k <= L / 2; ++k)
    for (int n = 0; n < L; ++n) {
      const double w = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
      X[k] += (x[n] - mean) * w * std::polar(1.0, -2.0 * std::numbers::pi * k * n / L);
    }
  return X;
}

TEST(HannSegmentTransform, TransformsOfTwoLengthsAliveTogetherAreTheWindowedDft) {
  HannSegmentTransform short_a(16), long_a(64), short_b(16);
  const HannSegmentTransform* transforms[] = {&short_a, &long_a, &short_b};
  for (const HannSegmentTransform* t : transforms)
    EXPECT_NEAR(t->window_power(), 3.0 * t->length() / 8.0, 1e-12) << "length " << t->length();
  for (int trial = 0; trial < 2; ++trial) {
    for (HannSegmentTransform* t : {&short_a, &long_a, &short_b}) {
      std::vector<double> x(t->length());
      for (int n = 0; n < t->length(); ++n)
        x[n] = 3.0 + std::sin(0.7 * n + trial + t->length()) + 0.25 * std::cos(2.3 * n * (t == &short_b ? 1.1 : 1.0));
      const std::vector<std::complex<double>>& X = t->transform(x.data());
      const std::vector<std::complex<double>> reference = hann_windowed_dft(x);
      ASSERT_EQ(X.size(), reference.size());
      for (std::size_t k = 0; k < X.size(); ++k)
        EXPECT_LT(std::abs(X[k] - reference[k]), 1e-12 * t->length()) << "length " << t->length() << " bin " << k;
    }
  }
}

// Transforms made, used and dropped on several threads at once (a sweep's runs, the
// recorder's helper threads), through transform() and add_power(): the lengths here are
// used by no other test, so their FFTW windows and plans are made by whichever thread
// comes first while the others wait, then used by all. Every transform is the direct DFT
// and every periodogram its squared magnitude; tests/scripts/test_threads.py runs this
// under Helgrind.
TEST(HannSegmentTransform, TransformsOnSeveralThreadsAtOnceAreTheWindowedDft) {
  std::atomic<int> wrong_bins{0}, transforms_done{0};
  std::vector<std::thread> threads;
  for (int thread = 0; thread < 4; ++thread)
    threads.emplace_back([thread, &wrong_bins, &transforms_done] {
      for (int round = 0; round < 6; ++round)
        for (int length : {24, 40, 96}) {
          HannSegmentTransform transform(length);
          std::vector<double> x(length);
          for (int n = 0; n < length; ++n) x[n] = std::sin(0.3 * n * (thread + 1) + round) + 0.1 * n;
          const std::vector<std::complex<double>>& X = transform.transform(x.data());
          const std::vector<std::complex<double>> reference = hann_windowed_dft(x);
          for (std::size_t k = 0; k < reference.size(); ++k)
            if (!(k < X.size() && std::abs(X[k] - reference[k]) < 1e-12 * length)) ++wrong_bins;
          // The periodogram's sums through the thread's own scratch (Welch's path).
          std::vector<double> sums(length / 2 + 1, 0.0);
          transform.add_power(x.data(), sums.data());
          for (std::size_t k = 0; k < reference.size(); ++k)
            if (!(std::abs(sums[k] - std::norm(reference[k])) < 1e-11 * length * length)) ++wrong_bins;
          ++transforms_done;
        }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(transforms_done.load(), 4 * 6 * 3);
  EXPECT_EQ(wrong_bins.load(), 0);
}

// The periodogram's sums as Welch keeps them (add_power: the bins stay in the thread's
// scratch), added for two different segments onto sums that already hold something,
// against the squared magnitudes of the direct DFT; another transform of the same length
// adding its own segment in between (the recorder's other columns) changes nothing.
TEST(HannSegmentTransform, AddedPowerIsTheSquaredMagnitudeOfTheWindowedDft) {
  const int length = 32;
  HannSegmentTransform transform(length), other(length);
  std::vector<double> x(length), z(length), y(length);
  for (int n = 0; n < length; ++n) {
    x[n] = 1.5 + std::sin(0.9 * n) - 0.3 * std::cos(2.1 * n);
    z[n] = -0.7 + 2.0 * std::cos(0.35 * n + 0.2);
    y[n] = std::cos(0.2 * n * n);
  }
  std::vector<double> sums(length / 2 + 1, 0.5), other_sums(length / 2 + 1, 0.0);
  transform.add_power(x.data(), sums.data());
  other.add_power(y.data(), other_sums.data());
  transform.add_power(z.data(), sums.data());
  const std::vector<std::complex<double>> X = hann_windowed_dft(x), Z = hann_windowed_dft(z), Y = hann_windowed_dft(y);
  for (int k = 0; k <= length / 2; ++k) {
    EXPECT_NEAR(sums[k], 0.5 + std::norm(X[k]) + std::norm(Z[k]), 1e-11 * length * length) << "bin " << k;
    EXPECT_NEAR(other_sums[k], std::norm(Y[k]), 1e-11 * length * length) << "bin " << k;
  }
}

TEST(HannSegmentTransform, OddOrTooShortLengthsAreRefused) {
  EXPECT_THROW(HannSegmentTransform(2), std::invalid_argument);
  EXPECT_THROW(HannSegmentTransform(15), std::invalid_argument);
  EXPECT_NO_THROW(HannSegmentTransform(4));
}

}  // namespace
}  // namespace heavesim::stats
