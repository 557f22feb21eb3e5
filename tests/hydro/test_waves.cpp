// Waves: the dispersion relation against its closed-form limits, regular-wave
// kinematics, spectra against closed-form moments, and H6 (irregular sea generation).
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "hydro/waves/dispersion.hpp"
#include "hydro/waves/wave_spectrum.hpp"
#include "hydro/waves/wave_train.hpp"

namespace heavesim::hydro {
namespace {

constexpr double g = 9.81;

TEST(HydroWaves, DispersionDeepWaterIsClosedForm) {
  for (double w : {0.2, 0.6, 1.0, 2.5}) EXPECT_DOUBLE_EQ(wave_number(w, infinite_depth, g), w * w / g);
}

TEST(HydroWaves, DispersionSatisfiesTheRelationAtFiniteDepth) {
  for (double h : {1.0, 10.0, 50.0, 300.0})
    for (double w : {0.05, 0.3, 1.0, 3.0}) {
      const double k = wave_number(w, h, g);
      EXPECT_NEAR(g * k * std::tanh(k * h), w * w, 1e-13 * w * w) << "h = " << h << ", w = " << w;
    }
}

TEST(HydroWaves, DispersionLimits) {
  // Shallow water: k h -> 0 gives w = k sqrt(g h); the first correction is
  // w^2 = g h k^2 (1 - (k h)^2 / 3), so at k h = 1e-3 the relative error is ~1.7e-7.
  const double h = 1.0, w_shallow = 1e-3 * std::sqrt(g / h);
  EXPECT_NEAR(wave_number(w_shallow, h, g), w_shallow / std::sqrt(g * h), 2e-7 * w_shallow / std::sqrt(g * h));
  // Deep water reached from a finite depth: k h = 40 (tanh = 1 - 4e-35).
  const double w_deep = std::sqrt(g * 40.0 / 100.0);
  EXPECT_DOUBLE_EQ(wave_number(w_deep, 100.0, g), w_deep * w_deep / g);
  // Group speed: half the phase speed in deep water, equal to it in shallow water.
  EXPECT_DOUBLE_EQ(group_speed(1.0, infinite_depth, g), 0.5 * phase_speed(1.0, infinite_depth, g));
  EXPECT_NEAR(group_speed(w_shallow, h, g) / phase_speed(w_shallow, h, g), 1.0, 1e-6);
}

TEST(HydroWaves, RegularWaveElevationAndPropagation) {
  const double H = 4.0, T = 10.0, heading = M_PI / 6.0;
  const WaveTrain wave = regular_wave(H, T, heading, 0.0, infinite_depth, {}, g);
  EXPECT_DOUBLE_EQ(wave.elevation(0.0, 0.0, 0.0), 2.0);  // crest at the origin at t = 0
  // The crest travels along the heading at the phase speed.
  const double c = phase_speed(2.0 * M_PI / T, infinite_depth, g);
  const double t = 3.7;
  EXPECT_NEAR(wave.elevation(t, c * t * std::cos(heading), c * t * std::sin(heading)), 2.0, 1e-12);
  // Half a wavelength ahead is a trough; perpendicular to the heading nothing changes.
  const double k = wave.components()[0].wave_number;
  EXPECT_NEAR(wave.elevation(0.0, M_PI / k * std::cos(heading), M_PI / k * std::sin(heading)), -2.0, 1e-12);
  EXPECT_NEAR(wave.elevation(1.3, -50.0 * std::sin(heading), 50.0 * std::cos(heading)), wave.elevation(1.3), 1e-12);
}

TEST(HydroWaves, Ramps) {
  const Ramp cosine{RampKind::cosine, 20.0}, tanh_ramp{RampKind::hyperbolic_tangent, 20.0};
  EXPECT_EQ(cosine(0.0), 0.0);
  EXPECT_DOUBLE_EQ(cosine(10.0), 0.5);
  EXPECT_EQ(cosine(20.0), 1.0);
  EXPECT_EQ(cosine(25.0), 1.0);
  EXPECT_NEAR(tanh_ramp(20.0), std::tanh(3.0), 1e-15);
  const WaveTrain ramped = regular_wave(2.0, 8.0, 0.0, 0.0, infinite_depth, cosine, g);
  EXPECT_DOUBLE_EQ(ramped.elevation(10.0), 0.5 * regular_wave(2.0, 8.0).elevation(10.0));
}

// The elevation of components with their own headings (an odd count: the two-lane sum and
// its scalar tail) against the sum of cosines written out here, up to 3 hours and 300 m
// from the origin: within a few ulp of each term.
TEST(HydroWaves, ElevationIsTheSumOfItsComponents) {
  std::vector<WaveComponent> components;
  for (int j = 0; j < 7; ++j) {
    const double w = 0.3 + 0.37 * j;
    components.push_back({0.2 + 0.1 * j, w, wave_number(w, infinite_depth, g), -1.0 + 0.45 * j, 0.9 * j + 0.1});
  }
  const WaveTrain sea(components);
  for (const auto& [t, x, y] : {std::tuple{0.0, 0.0, 0.0}, std::tuple{12.3, -4.0, 7.5}, std::tuple{10799.7, 300.0, -120.0}}) {
    double expected = 0.0, scale = 0.0;
    for (const WaveComponent& c : components) {
      expected += c.amplitude * std::cos(c.angular_frequency * t -
                                         c.wave_number * (x * std::cos(c.heading) + y * std::sin(c.heading)) + c.phase);
      scale += c.amplitude;
    }
    // The phase itself carries eps |w t| ~ 1e-12 rad of rounding at 3 hours.
    EXPECT_NEAR(sea.elevation(t, x, y), expected, 1e-11 * scale) << "t " << t;
  }
}

/// int_a^b f by composite Simpson with n (even) panels.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

TEST(HydroWaves, PiersonMoskowitzMomentsAreClosedForm) {
  // S = A w^-5 exp(-B w^-4): m_n = (A/4) B^((n-4)/4) Gamma((4-n)/4), so m0 = Hs^2/16,
  // and T_z = 2 pi sqrt(m0/m2) = Tp / (5 pi / 4)^(1/4).
  const PiersonMoskowitz pm{4.0, 10.0};
  const double wp = 2 * M_PI / 10.0;
  const double m0 = simpson(pm, 0.05 * wp, 60 * wp, 200000) + 5.0 / 64.0 * 16.0 * std::pow(1.0 / 60, 4);
  EXPECT_NEAR(m0, 1.0, 1e-8);
  // Peak at wp: dS/dw = 0 there.
  EXPECT_NEAR((pm(wp * (1 + 1e-5)) - pm(wp * (1 - 1e-5))) / pm(wp), 0.0, 1e-8);
}

TEST(HydroWaves, JonswapNormalizationAgreesWithDnvApproximation) {
  for (double gamma : {1.0, 2.0, 3.3, 5.0}) {
    const Jonswap j(3.0, 9.0, gamma);
    EXPECT_NEAR(j.normalization(), 1.0 - 0.287 * std::log(gamma), 0.012) << "gamma = " << gamma;
    const double wp = 2 * M_PI / 9.0;
    EXPECT_NEAR(simpson(j, 0.05 * wp, 60 * wp, 200000) + j.normalization() * 5.0 / 64.0 * 9.0 * std::pow(1.0 / 60, 4),
                9.0 / 16.0, 1e-7);
  }
  const PiersonMoskowitz pm{3.0, 9.0};
  EXPECT_NEAR(Jonswap(3.0, 9.0, 1.0)(0.8) / pm(0.8), 1.0, 1e-9);
  EXPECT_EQ(default_peak_enhancement(4.0, 7.0), 5.0);
  EXPECT_EQ(default_peak_enhancement(1.0, 12.0), 1.0);
  EXPECT_DOUBLE_EQ(default_peak_enhancement(4.0, 8.6), std::exp(5.75 - 1.15 * 4.3));
}

struct RecordStatistics {
  double hm0;             // 4 sigma [m]
  double zero_crossing;   // mean zero up-crossing period [s]
};

RecordStatistics record_statistics(const WaveTrain& sea, double duration, double dt) {
  const int n = static_cast<int>(duration / dt);
  double sum = 0.0, sum2 = 0.0, previous = sea.elevation(0.0);
  int upcrossings = 0;
  double first = -1.0, last = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = i * dt, eta = sea.elevation(t);
    sum += eta;
    sum2 += eta * eta;
    if (i > 0 && previous < 0.0 && eta >= 0.0) {
      const double crossing = t - dt * eta / (eta - previous);
      if (first < 0.0) first = crossing;
      last = crossing;
      ++upcrossings;
    }
    previous = eta;
  }
  const double mean = sum / (n + 1);
  return {4.0 * std::sqrt(sum2 / (n + 1) - mean * mean), (last - first) / (upcrossings - 1)};
}

// H6: 3-hour records of JONSWAP and PM seas; H_m0 = 4 sigma of the elevation record
// within 1 % of the target, T_z from zero up-crossings against 2 pi sqrt(m0/m2) of the
// target spectrum, and the discretized spectrum's peak at T_p.
TEST(HydroWaves, H6IrregularSeaReproducesTargetSpectrum) {
  const double Hs = 6.0, Tp = 12.0, wp = 2 * M_PI / Tp;
  for (auto discretization : {FrequencyDiscretization::equal_spacing, FrequencyDiscretization::equal_energy}) {
    for (double gamma : {1.0, 3.3}) {
      const Jonswap spectrum(Hs, Tp, gamma);
      IrregularSeaSettings settings;
      settings.min_frequency = 0.3 * wp;
      settings.max_frequency = 6.0 * wp;
      settings.num_components = 1000;
      settings.discretization = discretization;
      settings.seed = 42;
      const WaveTrain sea = irregular_sea(spectrum, settings);
      const RecordStatistics stats = record_statistics(sea, 3 * 3600.0, 0.25);
      EXPECT_NEAR(stats.hm0 / Hs, 1.0, 0.01) << "gamma " << gamma;
      const double m0 = simpson(spectrum, settings.min_frequency, settings.max_frequency, 20000);
      const double m2 = simpson([&](double w) { return w * w * spectrum(w); }, settings.min_frequency,
                                settings.max_frequency, 20000);
      EXPECT_NEAR(stats.zero_crossing / (2 * M_PI * std::sqrt(m0 / m2)), 1.0, 0.03) << "gamma " << gamma;
      if (discretization == FrequencyDiscretization::equal_spacing) {
        // Peak of a_j^2 / (2 dw): within one bin of wp.
        const auto& c = sea.components();
        int peak = 0;
        for (int j = 1; j < static_cast<int>(c.size()); ++j)
          if (c[j].amplitude > c[peak].amplitude) peak = j;
        const double dw = (settings.max_frequency - settings.min_frequency) / settings.num_components;
        EXPECT_NEAR(c[peak].angular_frequency, wp, dw);
      }
      if (gamma == 1.0) {  // PM closed form T_z = Tp (5 pi/4)^(-1/4), band-limited
        EXPECT_NEAR(stats.zero_crossing / (Tp * std::pow(5 * M_PI / 4, -0.25)), 1.0, 0.04);
      }
    }
  }
}

TEST(HydroWaves, SeedsAreReproducibleAndDistinct) {
  IrregularSeaSettings a, b;
  b.seed = 2;
  const PiersonMoskowitz pm{2.0, 8.0};
  EXPECT_EQ(irregular_sea(pm, a).elevation(123.0), irregular_sea(pm, a).elevation(123.0));
  EXPECT_NE(irregular_sea(pm, a).elevation(123.0), irregular_sea(pm, b).elevation(123.0));
}

}  // namespace
}  // namespace heavesim::hydro
