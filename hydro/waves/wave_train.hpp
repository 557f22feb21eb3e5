#pragma once
// Long-crested linear (Airy) sea as a sum of regular components. World frame: z up,
// origin on the mean free surface; heading beta is the direction the waves travel,
// measured from +x toward +y (beta = 0: waves travel along +x). Elevation
//   eta(x, y, t) = R(t) sum_j a_j cos(w_j t - k_j (x cos beta_j + y sin beta_j) + phi_j),
// i.e. the WAMIT convention eta = Re[a e^{i w t} e^{-i k (x cos b + y sin b)}]
// (docs/physics/waves.md §1): the crest is at the origin at t = 0 when phi = 0.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "hydro/waves/dispersion.hpp"
#include "hydro/waves/ramp.hpp"

namespace heavesim::hydro {

struct WaveComponent {
  double amplitude;          // a [m], half the wave height
  double angular_frequency;  // w [rad/s]
  double wave_number;        // k [rad/m], from the dispersion relation
  double heading;            // beta [rad]
  double phase;              // phi [rad]
};

class WaveTrain {
 public:
  WaveTrain() = default;
  WaveTrain(std::vector<WaveComponent> components, Ramp ramp = {}, double depth = infinite_depth);

  /// Free-surface elevation eta [m] at world point (x, y) [m] and time t [s].
  double elevation(double t, double x = 0.0, double y = 0.0) const;

  const std::vector<WaveComponent>& components() const { return components_; }
  const Ramp& ramp() const { return ramp_; }
  double depth() const { return depth_; }  // h [m]
  /// Variance sum a_j^2 / 2 [m^2] of the stationary (ramped-up) sea.
  double variance() const;

 private:
  std::vector<WaveComponent> components_;
  Ramp ramp_;
  double depth_ = infinite_depth;
  // The components as arrays, the heading's trigonometry done once: the elevation is one
  // pass, eta = sum a_j cos(w_j t - kx_j x - ky_j y + phi_j), with a vector cos (the
  // recorder asks for it at every sample; per component three libm calls were 7 % of a
  // 3-hour run).
  Eigen::ArrayXd amplitude_, angular_frequency_, wave_number_x_, wave_number_y_, phase_;
};

/// A regular wave of height H [m] (amplitude H/2), period T [s], heading beta [rad]
/// and phase phi [rad], in water of depth h [m].
WaveTrain regular_wave(double height, double period, double heading = 0.0, double phase = 0.0,
                       double depth = infinite_depth, Ramp ramp = {}, double gravity = 9.81);

enum class FrequencyDiscretization {
  equal_spacing,  // w_j = w_min + (j + 1/2) dw, a_j = sqrt(2 S(w_j) dw)
  equal_energy,   // bins of equal m0 / N; w_j at each bin's energy midpoint, a_j = sqrt(2 m0 / N)
};

struct IrregularSeaSettings {
  double min_frequency = 0.1;   // w_min [rad/s]
  double max_frequency = 3.0;   // w_max [rad/s]
  int num_components = 500;
  FrequencyDiscretization discretization = FrequencyDiscretization::equal_energy;
  unsigned long long seed = 1;  // random phases, uniform in [0, 2 pi)
  double heading = 0.0;         // beta [rad]
  double depth = infinite_depth;  // h [m]
  double gravity = 9.81;        // g [m/s^2]
  Ramp ramp;
};

/// Random-phase realisation of the one-sided spectrum S(w) [m^2 s/rad] on
/// [w_min, w_max]; energy outside that band is dropped (choose the band wide enough).
WaveTrain irregular_sea(const std::function<double(double)>& spectrum, const IrregularSeaSettings& settings);

}  // namespace heavesim::hydro
