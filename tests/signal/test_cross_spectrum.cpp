// The H1 frequency-response estimator and the coherence (signal/cross_spectrum.hpp)
// against closed forms: a harmonic input and output on one bin, where H1 is the complex
// amplitude ratio exactly; white noise through a two-tap filter, whose response
// b0 + b1 e^(-2 pi i f / fs) is known at every frequency; the same with independent
// noise added to the output, where H1 stays unbiased and the coherence falls to
// |H|^2 Gxx / (|H|^2 Gxx + Gnn) (Bendat & Piersol 2010, §9.1).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "signal/cross_spectrum.hpp"
#include "tests/signal/random_signals.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::stats::test_cross_spectrum {
namespace {

using testing::RandomSource;
constexpr double pi = std::numbers::pi;

// x = a cos(w t + phi), y = Re[xi a e^(i (w t + phi))] with w on bin k0: the window's
// leakage is the same in X and Y, so conj(X) Y / |X|^2 = xi in every bin the sine reaches.
TEST(CrossSpectrum, HarmonicOnABinGivesTheComplexAmplitudeRatio) {
  const int segment = 256, k0 = 12;
  const double fs = 2.0, f0 = k0 * fs / segment, amplitude = 1.7, phase = 0.3;
  const std::complex<double> xi = std::polar(0.8, -2.1);
  std::vector<double> x, y;
  for (int n = 0; n < 4096; ++n) {
    const double theta = 2 * pi * f0 * n / fs + phase;
    x.push_back(amplitude * std::cos(theta));
    y.push_back(std::real(xi * amplitude * std::exp(std::complex<double>(0.0, theta))));
  }
  const CrossSpectralEstimate e = cross_spectral_density(x, y, segment, fs);
  EXPECT_EQ(e.segments, 2 * 4096 / segment - 1);
  EXPECT_NEAR(e.frequencies[k0], f0, 1e-15);
  for (int k : {k0 - 1, k0, k0 + 1}) {
    EXPECT_NEAR(std::abs(e.transfer_function(k) - xi), 0.0, 1e-12) << "bin " << k;
    EXPECT_NEAR(e.coherence(k), 1.0, 1e-12) << "bin " << k;
  }
  // Parseval on the input: its variance a^2 / 2 is in the three bins.
  const double df = fs / segment;
  EXPECT_NEAR((e.input_density[k0 - 1] + e.input_density[k0] + e.input_density[k0 + 1]) * df,
              amplitude * amplitude / 2, 1e-10);
}

// y_n = b0 x_n + b1 x_(n-1): H(f) = b0 + b1 e^(-2 pi i f / fs) exactly. What keeps the
// estimate from it: the sample that crosses each segment's edge (damped by the window),
// and the per-segment mean removal, which differs between x and y segments and whose
// Hann transform reaches bin 1 (so bin 1 is left out: 3e-3 there, as scipy.signal.csd
// gives on the same record). The edge term is b1 x_(n-1) (w_n - w_(n-1)), a disturbance of
// relative power sum (dw)^2 / sum w^2 = 4 pi^2 / (3 L^2) = 5e-5 correlated with the input;
// averaged over the K = 255 segments it leaves a scatter of about sqrt(5e-5 / K) = 4.4e-4
// per bin. Bars 2e-3, about 4.5 of that, for the largest of 254 bins (measured 1.0e-3 in
// H and 6.7e-4 in 1 - coherence; scipy.signal.csd on a numpy record: 4.3e-4, 4.9e-4).
TEST(CrossSpectrum, TwoTapFilterResponseAtEveryFrequency) {
  const int n = 1 << 16, segment = 512;
  const double fs = 10.0, b0 = 0.6, b1 = -0.9;
  RandomSource random(11);
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = random.normal();
    y[i] = b0 * x[i] + (i > 0 ? b1 * x[i - 1] : 0.0);
  }
  const CrossSpectralEstimate e = cross_spectral_density(x, y, segment, fs);
  double worst = 0.0, worst_coherence = 0.0;
  for (int k = 2; k < segment / 2; ++k) {
    const std::complex<double> exact = b0 + b1 * std::exp(std::complex<double>(0.0, -2 * pi * e.frequencies[k] / fs));
    worst = std::max(worst, std::abs(e.transfer_function(k) - exact));
    worst_coherence = std::max(worst_coherence, 1.0 - e.coherence(k));
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(worst_coherence, 2e-3);
}

// Independent white noise of variance s_n^2 on the output: H1 still converges to H (its
// random error per bin ~ sqrt(1 - g^2) / (|g| sqrt(2 K)), K segments), and the coherence
// to |H|^2 / (|H|^2 + s_n^2) for a unit-variance white input (equal flat densities).
TEST(CrossSpectrum, OutputNoiseLeavesH1UnbiasedAndLowersTheCoherence) {
  const int n = 1 << 18, segment = 256;
  const double fs = 4.0, b0 = 1.0, b1 = 0.5, noise = 0.8;
  RandomSource random(17);
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = random.normal();
    y[i] = b0 * x[i] + (i > 0 ? b1 * x[i - 1] : 0.0) + noise * random.normal();
  }
  const CrossSpectralEstimate e = cross_spectral_density(x, y, segment, fs);
  double mean_gain_error = 0.0, mean_coherence_error = 0.0;
  const int bins = segment / 2 - 1;
  for (int k = 1; k < segment / 2; ++k) {
    const std::complex<double> exact = b0 + b1 * std::exp(std::complex<double>(0.0, -2 * pi * e.frequencies[k] / fs));
    const double coherence = std::norm(exact) / (std::norm(exact) + noise * noise);
    const double random_error = std::sqrt(1 - coherence) / (std::sqrt(coherence) * std::sqrt(2.0 * e.segments));
    EXPECT_NEAR(std::abs(e.transfer_function(k) - exact) / std::abs(exact), 0.0, 5 * random_error) << "bin " << k;
    EXPECT_NEAR(e.coherence(k), coherence, 0.05) << "bin " << k;
    mean_gain_error += (std::abs(e.transfer_function(k)) / std::abs(exact) - 1) / bins;
    mean_coherence_error += (e.coherence(k) - coherence) / bins;
  }
  // Over 127 bins the random errors average out: what stays is bias. The coherence
  // estimate's bias is (1 - g^2)^2 / K (Bendat & Piersol, Table 9.1), < 1e-3 here.
  EXPECT_NEAR(mean_gain_error, 0.0, 2e-3);
  EXPECT_NEAR(mean_coherence_error, 0.0, 3e-3);
}

TEST(CrossSpectrum, RecordsOfUnequalLengthOrTooShortAreRefused) {
  const std::vector<double> a(100, 1.0), b(99, 1.0);
  EXPECT_THROW(cross_spectral_density(a, b, 16, 1.0), std::invalid_argument);
  EXPECT_THROW(cross_spectral_density(a, a, 128, 1.0), std::invalid_argument);
  EXPECT_THROW(cross_spectral_density(a, a, 15, 1.0), std::invalid_argument);
  EXPECT_THROW(cross_spectral_density(a, a, 16, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace heavesim::stats::test_cross_spectrum
