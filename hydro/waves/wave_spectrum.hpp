#pragma once
// One-sided wave elevation spectra S(w) [m^2 s/rad] of angular frequency w [rad/s]
// (DNV-RP-C205 sec. 3.5.5; docs/physics/waves.md §3). Variance m0 = int S dw, and
// H_m0 = 4 sqrt(m0).
namespace heavesim::hydro {

/// Throws ParameterError("significant_height") unless Hs > 0, ParameterError("peak_period")
/// unless Tp is a wave period (check_wave_period, dispersion.hpp).
void check_sea_state(double significant_height, double peak_period);

/// Pierson-Moskowitz in the form of Hs and Tp:
///   S(w) = (5/16) Hs^2 wp^4 w^-5 exp(-5/4 (wp/w)^4),  wp = 2 pi / Tp,
/// whose integral over 0..inf is exactly Hs^2/16 (the often printed 1.057 f_p is
/// (5/4)^(1/4) = 1.0574 rounded).
struct PiersonMoskowitz {
  double significant_height;  // Hs [m]
  double peak_period;         // Tp [s]
  double operator()(double w) const;
};

/// JONSWAP: S_J(w) = N(gamma) S_PM(w) gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)),
/// sigma = 0.07 (w <= wp) or 0.09. N(gamma) is computed by quadrature at
/// construction so that m0 = Hs^2/16 exactly; DNV's closed approximation
/// C(gamma) = 1 - 0.287 ln(gamma) is within about 1 % of it (see the tests).
class Jonswap {
 public:
  Jonswap(double significant_height, double peak_period, double peak_enhancement = 3.3);
  double operator()(double w) const;
  double significant_height() const { return significant_height_; }
  double peak_period() const { return peak_period_; }
  double peak_enhancement() const { return gamma_; }
  double normalization() const { return normalization_; }  // N(gamma) [-]

 private:
  double unnormalized(double w) const;
  double significant_height_, peak_period_, gamma_, normalization_ = 1.0;
};

/// DNV's default peak enhancement from Tp/sqrt(Hs): 5 if <= 3.6, 1 if >= 5,
/// exp(5.75 - 1.15 Tp/sqrt(Hs)) between.
double default_peak_enhancement(double significant_height, double peak_period);

}  // namespace heavesim::hydro
